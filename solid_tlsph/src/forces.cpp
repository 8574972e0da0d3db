// Forces: the acceleration of eq. 12 (the stress divergence over the reference pairs, with the
// hourglass penalty of the quadratic correction), gravity, external loads, pair and mass
// damping; the odd images' stress force handed to their partners.
#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

#include "fsi/core/error.hpp"
#include "fsi/core/parallel.hpp"
#include "shared.hpp"
#include "solid_tlsph/solid.hpp"

namespace fsi::tlsph {

template <int D> void BasicTlsphSolid<D>::compute_acceleration() {
  const double inv_rho0 = 1.0 / rho0_;
  const double nu_d = options_.pair_damping * 0.5 * c_s_ * h_;
  const double gamma = options_.mass_damping;
  const Vec gravity = options_.gravity;
  const bool hourglass = !pair_k_.empty();
  // Raw arrays, loaded once: the pair loops below hold their sums in registers.
  std::array<const double*, D * D> PB; // P B0 (quadratic: P), component (i, j) at D i + j
  for (std::size_t k = 0; k < D * D; ++k) PB[k] = PB_[k]->data();
  std::array<const double*, D> q, g, r;
  for (int k = 0; k < D; ++k)
    q[k] = pair_q_[k].data(), g[k] = pair_g_[k].data(), r[k] = pair_r_[k].data();
  const double *k_ab = pair_k_.data(), *dwr = pair_dwr_.data(), *V0 = V0_.data();
  const std::uint32_t *start = pair_start_.data(), *pb = pair_b_.data(), *rev = pair_rev_.data();
  const auto v = v_.coords();
  const std::size_t bad = parallel_reduce(
      size(), none,
      [&, PB, q, g, r, k_ab, dwr, V0, start, pb, rev, v](std::size_t a) {
        const bool image = image_partner_[a] != none;
        if (clamped_[a] && !image) return none;
        // eq. 12 per unit mass: (1 / rho0) sum_b (P_a B0_a + P_b B0_b) grad0 W_ab V_b
        Vec s = Vec::Zero(), d = Vec::Zero(); // stress and damping sums
        if (quadratic_) {
          // f_a / (rho0 V_a) = (1 / rho0) sum_b (P_a g~_ab - (V_b / V_a) P_b g~_ba)
          const double inv_Va = 1.0 / V0[a];
          for (std::uint32_t p = start[a]; p < start[a + 1]; ++p) {
            const std::uint32_t b = pb[p], pr = rev[p];
            const double s_b = V0[b] * inv_Va;
            double ga[D], gb[D];
            for (int j = 0; j < D; ++j) ga[j] = q[j][p], gb[j] = s_b * q[j][pr];
            for (int i = 0; i < D; ++i) {
              double t = PB[D * i][a] * ga[0];
              for (int j = 1; j < D; ++j) t += PB[D * i + j][a] * ga[j];
              for (int j = 0; j < D; ++j) t -= PB[D * i + j][b] * gb[j];
              s(i) += t;
            }
            if (hourglass) // -dPi_hg/dx_a = sum_b (k_ab r_ab - k_ba r_ba)
              for (int i = 0; i < D; ++i)
                s(i) += (k_ab[p] * r[i][p] - k_ab[pr] * r[i][pr]) * inv_Va;
            for (int i = 0; i < D; ++i) d(i) += (v[i][b] - v[i][a]) * dwr[p];
          }
        } else {
          for (std::uint32_t p = start[a]; p < start[a + 1]; ++p) {
            const std::uint32_t b = pb[p];
            for (int i = 0; i < D; ++i) {
              double t = (PB[D * i][a] + PB[D * i][b]) * g[0][p];
              for (int j = 1; j < D; ++j) t += (PB[D * i + j][a] + PB[D * i + j][b]) * g[j][p];
              s(i) += t;
            }
            for (int i = 0; i < D; ++i) d(i) += (v[i][b] - v[i][a]) * dwr[p];
          }
        }
        if (image) { // the stress force on the image (its own P is zero), for its partner
          for (int i = 0; i < D; ++i) image_a_[i][a] = s(i) * inv_rho0;
          return none;
        }
        const double inv_m = inv_rho0 / V0[a];
        bool finite = true;
        for (int i = 0; i < D; ++i) {
          a_[i][a] =
              s(i) * inv_rho0 + gravity(i) + f_[i][a] * inv_m + 2.0 * nu_d * d(i) - gamma * v[i][a];
          finite = finite && std::isfinite(a_[i][a]);
        }
        return finite ? none : a;
      },
      [](std::size_t a, std::size_t b) { return std::min(a, b); });
  if (bad != none) {
    std::ostringstream s;
    s << "tlsph: acceleration is not finite at particle " << bad << " (X0 = ";
    for (int k = 0; k < D; ++k) s << (k ? ", " : "") << X0_[k][bad];
    s << ") in step " << step_ << " at t = " << time_;
    throw RunError(s.str());
  }
  if (!images_) return;
  // f_p = -dPi/dx_p with x_g = X_g + s (x_p - X_p): s times the force on each image g, per unit
  // mass of p.
  parallel_for(size(), [&](std::size_t p) {
    for (std::uint32_t j = image_start_[p]; j < image_start_[p + 1]; ++j) {
      const std::size_t img = image_list_[j];
      const double r = image_sign_[img] * (V0_[img] / V0_[p]);
      for (int i = 0; i < D; ++i) a_[i][p] += r * image_a_[i][img];
    }
  });
}

template void BasicTlsphSolid<2>::compute_acceleration();
template void BasicTlsphSolid<3>::compute_acceleration();

} // namespace fsi::tlsph
