// The prior acceleration, frozen over an advection step: gravity and the viscous force (eq. 3)
// with no-slip walls (eqs. 15, 17).
#include "fluid_sph/sph_fluid.hpp"

#include "wall_terms.hpp"

#include "fsi/core/parallel.hpp"

namespace fsi::sph {

void SphFluid::prior_acceleration() {
  auto& f = fluid_;
  const Vec2 g = options_.gravity;
  const double mu = options_.rho0 * options_.viscosity, reg = 0.01 * h_;
  const double inv_m = 1.0 / mass_;
  parallel_for(f.size(), [&](std::size_t i) {
    double fx = 0.0, fy = 0.0;
    if (mu > 0.0) {
      // Viscous force 2 mu V_i sum_j V_j (v_i - v_j) dW / (r + 0.01 h) (eq. 3); no-slip walls
      // with the dummy velocity 2 v_w - v_i (eqs. 15, 17).
      const double vx_i = f.vx[i], vy_i = f.vy[i];
      for (std::uint32_t k = pstart_[i]; k < pstart_[i + 1]; ++k) {
        const std::uint32_t j = pj_[k];
        const double s = pdw_[k] * f.vol[j] / (pr_[k] + reg);
        fx += (vx_i - f.vx[j]) * s;
        fy += (vy_i - f.vy[j]) * s;
      }
      for (std::uint32_t k = wstart_[i]; k < wstart_[i + 1]; ++k) {
        const std::uint32_t a = wj_[k];
        const double s = wall_viscous_weight(wdw_[k], walls_.vol[a], wr_[k], reg);
        fx += (vx_i - walls_.vx[a]) * s;
        fy += (vy_i - walls_.vy[a]) * s;
      }
      const double c = 2.0 * mu * f.vol[i] * inv_m;
      fx *= c;
      fy *= c;
    }
    f.apx[i] = g.x() + fx;
    f.apy[i] = g.y() + fy;
  });
  if (tracked_ < walls_.size()) wall_viscous_reaction();
}

} // namespace fsi::sph
