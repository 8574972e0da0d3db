// The prior acceleration, frozen over an advection step: gravity and the viscous force (eq. 3)
// with no-slip walls (eqs. 15, 17).
#include "fluid_sph/sph_fluid.hpp"

#include "wall_terms.hpp"

#include "fsi/core/parallel.hpp"

namespace fsi::sph {

template <int D> void BasicSphFluid<D>::prior_acceleration() {
  auto& f = fluid_;
  const Vec g = options_.gravity;
  const double mu = options_.rho0 * options_.viscosity, reg = 0.01 * h_;
  const double inv_m = 1.0 / mass_;
  parallel_for(owned(), [&](std::size_t i) {
    double F[D] = {};
    if (mu > 0.0) {
      // Viscous force 2 mu V_i sum_j V_j (v_i - v_j) dW / (r + 0.01 h) (eq. 3); no-slip walls
      // with the dummy velocity 2 v_w - v_i (eqs. 15, 17).
      double v_i[D];
      FSI_UNROLL for (int c = 0; c < D; ++c) v_i[c] = f.v[c][i];
      for (std::uint32_t k = pstart_[i]; k < pstart_[i + 1]; ++k) {
        const std::uint32_t j = pj_[k];
        const double s = pdw_[k] * f.vol[j] / (pr_[k] + reg);
        FSI_UNROLL for (int c = 0; c < D; ++c) F[c] += (v_i[c] - f.v[c][j]) * s;
      }
      for (std::uint32_t k = wstart_[i]; k < wstart_[i + 1]; ++k) {
        const std::uint32_t a = wj_[k];
        const double s = wall_viscous_weight(wdw_[k], walls_.vol[a], wr_[k], reg);
        FSI_UNROLL for (int c = 0; c < D; ++c) F[c] += (v_i[c] - walls_.v[c][a]) * s;
      }
      const double scale = 2.0 * mu * f.vol[i] * inv_m;
      FSI_UNROLL for (int c = 0; c < D; ++c) F[c] *= scale;
    }
    FSI_UNROLL for (int c = 0; c < D; ++c) f.ap[c][i] = g[c] + F[c];
  });
  if (tracked_ < walls_.size()) wall_viscous_reaction();
}

template void BasicSphFluid<2>::prior_acceleration();
template void BasicSphFluid<3>::prior_acceleration();

} // namespace fsi::sph
