// Stress: Green-Lagrange strain (eq. 9) and first Piola-Kirchhoff stress P = F S (eq. 7) from
// the material law, P B0 per particle for the forces; von Mises for output.
#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <sstream>

#include "fsi/core/error.hpp"
#include "fsi/core/parallel.hpp"
#include "shared.hpp"
#include "solid_tlsph/solid.hpp"

namespace fsi::tlsph {

namespace {

template <int D>
void store(const std::array<std::vector<double>*, D * D>& t, std::size_t a, const MatD<D>& m) {
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j) (*t[D * i + j])[a] = m(i, j);
}

} // namespace

template <int D> void BasicTlsphSolid<D>::compute_stress() {
  const materials::MaterialInterface<D>& law = *material_;
  const std::size_t bad = parallel_reduce(
      size(), none,
      [&](std::size_t a) {
        const Mat F = deformation_gradient(a);
        store<D>(F_, a, F);
        // An odd-image clamp carries no strain energy: its F (the mirrored field's, one-sided
        // at the clamp's far side) enters no force and is not guarded.
        if (imaged(a)) {
          store<D>(PB_, a, Mat::Zero());
          return none;
        }
        const double J = F.determinant();
        if (!(J > 0.0)) { // also NaN
          store<D>(PB_, a, Mat::Zero());
          return a;
        }
        const Mat E = 0.5 * (F.transpose() * F - Mat::Identity()); // eq. 9
        // eq. 7, P B0 (quadratic: P itself, the correction is in g~_ab)
        const Mat P = F * law.stress(E);
        store<D>(PB_, a, quadratic_ ? P : Mat(P * correction_matrix(a)));
        if (!pair_k_.empty()) {
          std::array<double*, D> r;
          for (int k = 0; k < D; ++k) r[k] = &pair_r_[k][pair_start_[a]];
          hourglass_residuals(a, r);
        }
        return none;
      },
      [](std::size_t a, std::size_t b) { return std::min(a, b); });
  if (bad != none) {
    std::ostringstream s;
    Mat F;
    for (int i = 0; i < D; ++i)
      for (int j = 0; j < D; ++j) F(i, j) = (*F_[D * i + j])[bad];
    s << "tlsph: det F = " << F.determinant() << " <= 0 at particle " << bad << " (X0 = ";
    for (int k = 0; k < D; ++k) s << (k ? ", " : "") << X0_[k][bad];
    s << ") in step " << step_ << " at t = " << time_;
    throw RunError(s.str());
  }
}

template <int D> std::vector<double> BasicTlsphSolid<D>::von_mises() const {
  std::vector<double> out(size());
  const materials::MaterialInterface<D>& law = *material_;
  parallel_for(size(), [&](std::size_t i) {
    const Mat F = deformation_gradient(i);
    out[i] = materials::von_mises(law, F, Mat(0.5 * (F.transpose() * F - Mat::Identity())));
  });
  return out;
}

template void BasicTlsphSolid<2>::compute_stress();
template void BasicTlsphSolid<3>::compute_stress();
template std::vector<double> BasicTlsphSolid<2>::von_mises() const;
template std::vector<double> BasicTlsphSolid<3>::von_mises() const;

} // namespace fsi::tlsph
