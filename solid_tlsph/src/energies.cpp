// Energies: kinetic, strain (with the hourglass penalty's), gravity's potential, and the
// external work done so far.
#include <array>
#include <vector>

#include "fsi/core/parallel.hpp"
#include "solid_tlsph/solid.hpp"

namespace fsi::tlsph {

template <int D> TlsphEnergies BasicTlsphSolid<D>::energies() const {
  struct Sum {
    double k, s, g;
  };
  const materials::MaterialInterface<D>& law = *material_;
  const Vec g = options_.gravity;
  const Sum sum = parallel_reduce(
      size(), Sum{0.0, 0.0, 0.0},
      [&](std::size_t i) {
        const Mat F = deformation_gradient(i);
        const Mat E = 0.5 * (F.transpose() * F - Mat::Identity());
        const double m = rho0_ * V0_[i];
        if (imaged(i)) return Sum{0.0, 0.0, 0.0};
        double w = V0_[i] * law.energy(E);
        if (!pair_k_.empty()) { // Pi_hg = 1/2 sum_b k_ab |r_ab|^2
          const std::uint32_t start = pair_start_[i], count = pair_start_[i + 1] - start;
          std::array<std::vector<double>, D> r;
          std::array<double*, D> rp;
          for (int k = 0; k < D; ++k) r[k].resize(count), rp[k] = r[k].data();
          hourglass_residuals(i, rp);
          for (std::uint32_t q = 0; q < count; ++q) {
            double r2 = 0.0;
            for (int k = 0; k < D; ++k) r2 += r[k][q] * r[k][q];
            w += 0.5 * pair_k_[start + q] * r2;
          }
        }
        if (clamped_[i]) return Sum{0.0, w, 0.0};
        return Sum{0.5 * m * velocity(i).squaredNorm(), w, m * g.dot(displacement(i))};
      },
      [](Sum a, Sum b) {
        return Sum{a.k + b.k, a.s + b.s, a.g + b.g};
      });
  return {sum.k, sum.s, sum.g, external_work_};
}

template TlsphEnergies BasicTlsphSolid<2>::energies() const;
template TlsphEnergies BasicTlsphSolid<3>::energies() const;

} // namespace fsi::tlsph
