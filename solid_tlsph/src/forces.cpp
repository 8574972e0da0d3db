// Forces: the acceleration of eq. 12 (the stress divergence over the reference pairs, with the
// hourglass penalty of the quadratic correction), gravity, external loads, pair and mass
// damping; the odd images' stress force handed to their partners.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "fsi/core/error.hpp"
#include "fsi/core/parallel.hpp"
#include "shared.hpp"
#include "solid_tlsph/solid.hpp"

namespace fsi::tlsph {

void TlsphSolid::compute_acceleration() {
  const double inv_rho0 = 1.0 / rho0_;
  const double nu_d = options_.pair_damping * 0.5 * c_s_ * h_;
  const double gamma = options_.mass_damping;
  const double gx = options_.gravity.x(), gy = options_.gravity.y();
  const bool hourglass = !pair_k_.empty();
  const std::size_t bad = parallel_reduce(
      size(), none,
      [&](std::size_t a) {
        const bool image = image_partner_[a] != none;
        if (clamped_[a] && !image) return none;
        // eq. 12 per unit mass: (1 / rho0) sum_b (P_a B0_a + P_b B0_b) grad0 W_ab V_b
        double sx = 0.0, sy = 0.0, dx = 0.0, dy = 0.0;
        if (quadratic_) {
          // f_a / (rho0 V_a) = (1 / rho0) sum_b (P_a g~_ab - (V_b / V_a) P_b g~_ba)
          const double inv_Va = 1.0 / V0_[a];
          for (std::uint32_t p = pair_start_[a]; p < pair_start_[a + 1]; ++p) {
            const std::uint32_t b = pair_b_[p], r = pair_rev_[p];
            const double ga0 = pair_qx_[p], ga1 = pair_qy_[p];
            const double s_b = V0_[b] * inv_Va, gb0 = s_b * pair_qx_[r], gb1 = s_b * pair_qy_[r];
            sx += PB00_[a] * ga0 + PB01_[a] * ga1 - PB00_[b] * gb0 - PB01_[b] * gb1;
            sy += PB10_[a] * ga0 + PB11_[a] * ga1 - PB10_[b] * gb0 - PB11_[b] * gb1;
            if (hourglass) { // -dPi_hg/dx_a = sum_b (k_ab r_ab - k_ba r_ba)
              sx += (pair_k_[p] * pair_rx_[p] - pair_k_[r] * pair_rx_[r]) * inv_Va;
              sy += (pair_k_[p] * pair_ry_[p] - pair_k_[r] * pair_ry_[r]) * inv_Va;
            }
            dx += (vx_[b] - vx_[a]) * pair_dwr_[p], dy += (vy_[b] - vy_[a]) * pair_dwr_[p];
          }
        } else {
          for (std::uint32_t p = pair_start_[a]; p < pair_start_[a + 1]; ++p) {
            const std::uint32_t b = pair_b_[p];
            const double g0 = pair_gx_[p], g1 = pair_gy_[p];
            sx += (PB00_[a] + PB00_[b]) * g0 + (PB01_[a] + PB01_[b]) * g1;
            sy += (PB10_[a] + PB10_[b]) * g0 + (PB11_[a] + PB11_[b]) * g1;
            dx += (vx_[b] - vx_[a]) * pair_dwr_[p], dy += (vy_[b] - vy_[a]) * pair_dwr_[p];
          }
        }
        if (image) { // the stress force on the image (its own P is zero), for its partner
          image_ax_[a] = sx * inv_rho0, image_ay_[a] = sy * inv_rho0;
          return none;
        }
        const double inv_m = inv_rho0 / V0_[a];
        ax_[a] = sx * inv_rho0 + gx + fx_[a] * inv_m + 2.0 * nu_d * dx - gamma * vx_[a];
        ay_[a] = sy * inv_rho0 + gy + fy_[a] * inv_m + 2.0 * nu_d * dy - gamma * vy_[a];
        return std::isfinite(ax_[a]) && std::isfinite(ay_[a]) ? none : a;
      },
      [](std::size_t a, std::size_t b) { return std::min(a, b); });
  if (bad != none) {
    std::ostringstream s;
    s << "tlsph: acceleration is not finite at particle " << bad << " (X0 = " << X0_[bad] << ", "
      << Y0_[bad] << ") in step " << step_ << " at t = " << time_;
    throw RunError(s.str());
  }
  if (!images_) return;
  // f_p = -dPi/dx_p with x_g = X_g - (x_p - X_p): minus the force on the image g, per unit
  // mass of p.
  parallel_for(size(), [&](std::size_t p) {
    const std::size_t g = image_of_[p];
    if (g == none) return;
    const double r = V0_[g] / V0_[p];
    ax_[p] -= r * image_ax_[g], ay_[p] -= r * image_ay_[g];
  });
}

} // namespace fsi::tlsph
