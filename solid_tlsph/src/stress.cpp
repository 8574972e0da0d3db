// Stress: Green-Lagrange strain (eq. 9) and first Piola-Kirchhoff stress P = F S (eq. 7) from
// the material law, P B0 per particle for the forces; von Mises for output.
#include <Eigen/LU>
#include <algorithm>
#include <sstream>

#include "fsi/core/error.hpp"
#include "fsi/core/parallel.hpp"
#include "shared.hpp"
#include "solid_tlsph/solid.hpp"

namespace fsi::tlsph {

void TlsphSolid::compute_stress() {
  const materials::Material& law = *material_;
  const std::size_t bad = parallel_reduce(
      size(), none,
      [&](std::size_t a) {
        const Mat2 F = deformation_gradient(a);
        F00_[a] = F(0, 0), F01_[a] = F(0, 1), F10_[a] = F(1, 0), F11_[a] = F(1, 1);
        // An odd-image clamp carries no strain energy: its F (the mirrored field's, one-sided
        // at the clamp's far side) enters no force and is not guarded.
        if (imaged(a)) {
          PB00_[a] = PB01_[a] = PB10_[a] = PB11_[a] = 0.0;
          return none;
        }
        const double J = F.determinant();
        if (!(J > 0.0)) { // also NaN
          PB00_[a] = PB01_[a] = PB10_[a] = PB11_[a] = 0.0;
          return a;
        }
        const Mat2 E = 0.5 * (F.transpose() * F - Mat2::Identity()); // eq. 9
        // eq. 7, P B0 (quadratic: P itself, the correction is in g~_ab)
        const Mat2 P = F * law.stress(E);
        const Mat2 PB = quadratic_ ? P : Mat2(P * correction_matrix(a));
        PB00_[a] = PB(0, 0), PB01_[a] = PB(0, 1), PB10_[a] = PB(1, 0), PB11_[a] = PB(1, 1);
        if (!pair_k_.empty())
          hourglass_residuals(a, &pair_rx_[pair_start_[a]], &pair_ry_[pair_start_[a]]);
        return none;
      },
      [](std::size_t a, std::size_t b) { return std::min(a, b); });
  if (bad != none) {
    std::ostringstream s;
    s << "tlsph: det F = " << F00_[bad] * F11_[bad] - F01_[bad] * F10_[bad] << " <= 0 at particle "
      << bad << " (X0 = " << X0_[bad] << ", " << Y0_[bad] << ") in step " << step_
      << " at t = " << time_;
    throw RunError(s.str());
  }
}

std::vector<double> TlsphSolid::von_mises() const {
  std::vector<double> out(size());
  const materials::Material& law = *material_;
  parallel_for(size(), [&](std::size_t i) {
    const Mat2 F = deformation_gradient(i);
    out[i] = materials::von_mises(law, F, 0.5 * (F.transpose() * F - Mat2::Identity()));
  });
  return out;
}

} // namespace fsi::tlsph
