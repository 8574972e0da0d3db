// The acoustic step's first half: density and position by dt/2, pressure by the equation of
// state (eq. 2), and the momentum equation (eqs. 3-5, 18, 20) with the Riemann dissipation between
// fluid pairs and the wall terms (eqs. 15-17).
#include "fluid_sph/sph_fluid.hpp"

#include "wall_terms.hpp"

#include "fsi/core/parallel.hpp"

namespace fsi::sph {

void SphFluid::first_half(double dt) {
  auto& f = fluid_;
  const double half = 0.5 * dt, c2 = options_.c0 * options_.c0, rho0 = options_.rho0;
  parallel_for(f.size(), [&](std::size_t i) {
    f.rho[i] += f.drho[i] * half;
    f.p[i] = c2 * (f.rho[i] - rho0); // eq. 2
    f.x[i] += f.vx[i] * half;
    f.y[i] += f.vy[i] * half;
  });
  const double rho0c0 = rho0 * options_.c0, inv_c0 = 1.0 / options_.c0, inv_m = 1.0 / mass_;
  const bool lim = options_.riemann_limiter;
  const double rho0c0_pairs = options_.pair_dissipation ? rho0c0 : 0.0;
  parallel_for(f.size(), [&](std::size_t i) {
    const double p_i = f.p[i], vx_i = f.vx[i], vy_i = f.vy[i];
    const double b00 = f.b00[i], b01 = f.b01[i], b11 = f.b11[i];
    double fx = 0.0, fy = 0.0;
    for (std::uint32_t k = pstart_[i]; k < pstart_[i + 1]; ++k) {
      const std::uint32_t j = pj_[k];
      const double ex = pex_[k], ey = pey_[k], dWV = pdw_[k] * f.vol[j];
      const double p_j = f.p[j];
      // (p_i B_j + p_j B_i) grad W_ij V_j (eqs. 18, 20).
      const double gx = dWV * ex, gy = dWV * ey;
      fx -= p_i * (f.b00[j] * gx + f.b01[j] * gy) + p_j * (b00 * gx + b01 * gy);
      fy -= p_i * (f.b01[j] * gx + f.b11[j] * gy) + p_j * (b01 * gx + b11 * gy);
      // Riemann dissipation: -2 (P* - p_bar) grad W = beta rho0 c0 u grad W (eq. 5).
      const double u = (vx_i - f.vx[j]) * ex + (vy_i - f.vy[j]) * ey;
      const double d = rho0c0_pairs * limiter(u, inv_c0, lim) * u;
      fx += d * gx;
      fy += d * gy;
    }
    // Walls (eqs. 15-17): dummy pressure p_d = p_i + rho_i r max(0, (a_prior - a_w) . (-e_ia)).
    const double apx = f.apx[i], apy = f.apy[i], rho_i = f.rho[i];
    for (std::uint32_t k = wstart_[i]; k < wstart_[i + 1]; ++k) {
      const std::uint32_t a = wj_[k];
      const Vec2 t =
          wall_term({p_i, rho_i, wr_[k], apx - walls_.ax[a], apy - walls_.ay[a], wex_[k], wey_[k],
                     wdw_[k] * walls_.vol[a], b00, b01, b11, vx_i - walls_.vx[a],
                     vy_i - walls_.vy[a], walls_.nx[a], walls_.ny[a], rho0c0, inv_c0, lim});
      fx += t.x();
      fy += t.y();
    }
    const double s = f.vol[i] * inv_m;
    f.ax[i] = fx * s + apx;
    f.ay[i] = fy * s + apy;
  });
}

} // namespace fsi::sph
