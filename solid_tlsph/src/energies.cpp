// Energies: kinetic, strain (with the hourglass penalty's), gravity's potential, and the
// external work done so far.
#include <vector>

#include "fsi/core/parallel.hpp"
#include "solid_tlsph/solid.hpp"

namespace fsi::tlsph {

TlsphEnergies TlsphSolid::energies() const {
  struct Sum {
    double k, s, g;
  };
  const materials::Material& law = *material_;
  const Vec2 g = options_.gravity;
  const Sum sum = parallel_reduce(
      size(), Sum{0.0, 0.0, 0.0},
      [&](std::size_t i) {
        const Mat2 F = deformation_gradient(i);
        const Mat2 E = 0.5 * (F.transpose() * F - Mat2::Identity());
        const double m = rho0_ * V0_[i];
        if (imaged(i)) return Sum{0.0, 0.0, 0.0};
        double w = V0_[i] * law.energy(E);
        if (!pair_k_.empty()) { // Pi_hg = 1/2 sum_b k_ab |r_ab|^2
          const std::uint32_t start = pair_start_[i], count = pair_start_[i + 1] - start;
          std::vector<double> rx(count), ry(count);
          hourglass_residuals(i, rx.data(), ry.data());
          for (std::uint32_t q = 0; q < count; ++q)
            w += 0.5 * pair_k_[start + q] * (rx[q] * rx[q] + ry[q] * ry[q]);
        }
        if (clamped_[i]) return Sum{0.0, w, 0.0};
        return Sum{0.5 * m * (vx_[i] * vx_[i] + vy_[i] * vy_[i]), w,
                   m * (g.x() * (x_[i] - X0_[i]) + g.y() * (y_[i] - Y0_[i]))};
      },
      [](Sum a, Sum b) {
        return Sum{a.k + b.k, a.s + b.s, a.g + b.g};
      });
  return {sum.k, sum.s, sum.g, external_work_};
}

} // namespace fsi::tlsph
