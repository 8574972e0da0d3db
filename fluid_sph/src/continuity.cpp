// The acoustic step's second half: velocity by dt and position by dt/2, the continuity equation
// (eqs. 3, 5) with the walls' terms (eq. 16), density by dt/2, and the acoustic criterion.
#include "fluid_sph/sph_fluid.hpp"

#include "wall_terms.hpp"

#include "fsi/core/parallel.hpp"

#include <algorithm>
#include <cmath>

namespace fsi::sph {

void SphFluid::second_half(double dt) {
  auto& f = fluid_;
  const double half = 0.5 * dt;
  parallel_for(f.size(), [&](std::size_t i) {
    f.vx[i] += f.ax[i] * dt;
    f.vy[i] += f.ay[i] * dt;
    f.x[i] += f.vx[i] * half;
    f.y[i] += f.vy[i] * half;
  });
  const double inv_rho0c0 = 1.0 / (options_.rho0 * options_.c0);
  const double c0 = options_.c0, four_h = 4.0 * h_;
  const double worst = parallel_reduce(
      f.size(), 0.0,
      [&](std::size_t i) {
        const double p_i = f.p[i], vx_i = f.vx[i], vy_i = f.vy[i];
        double s = 0.0;
        // Continuity (eqs. 3, 5): rho_i sum [(v_i - v_j) . e_ij + (p_i - p_j) / (rho0 c0)] dW V_j.
        for (std::uint32_t k = pstart_[i]; k < pstart_[i + 1]; ++k) {
          const std::uint32_t j = pj_[k];
          const double u = (vx_i - f.vx[j]) * pex_[k] + (vy_i - f.vy[j]) * pey_[k];
          s += (u + (p_i - f.p[j]) * inv_rho0c0) * pdw_[k] * f.vol[j];
        }
        // Walls: v_d = 2 v_w - v_i, so v_i - v_d = 2 (v_i - v_w); the pressure term with the
        // dummy pressure p_d of eq. 16 (the reference code's wall density diffusion).
        const double apx = f.apx[i], apy = f.apy[i], rho_i = f.rho[i];
        for (std::uint32_t k = wstart_[i]; k < wstart_[i + 1]; ++k) {
          const std::uint32_t a = wj_[k];
          const double ex = wex_[k], ey = wey_[k];
          const double u = (vx_i - walls_.vx[a]) * ex + (vy_i - walls_.vy[a]) * ey;
          const double p_id =
              -dummy_jump(rho_i, wr_[k], apx - walls_.ax[a], apy - walls_.ay[a], ex, ey);
          s += (2.0 * u + p_id * inv_rho0c0) * wdw_[k] * walls_.vol[a];
        }
        f.drho[i] = f.rho[i] * s;
        f.rho[i] += f.drho[i] * half;
        // Acoustic criterion: max(c0 + |v|, sqrt(4 h |a|)).
        const double v = std::sqrt(vx_i * vx_i + vy_i * vy_i);
        const double a = std::sqrt(f.ax[i] * f.ax[i] + f.ay[i] * f.ay[i]);
        return std::max(c0 + v, std::sqrt(four_h * a));
      },
      [](double a, double b) { return std::max(a, b); }); // NaN-safe: a NaN is caught by guard()
  dt_acoustic_ = options_.acoustic_cfl * h_ / worst;
}

} // namespace fsi::sph
