// The acoustic step's second half: velocity by dt and position by dt/2, the continuity equation
// (eqs. 3, 5) with the walls' terms (eq. 16), density by dt/2, and the acoustic criterion.
#include "fluid_sph/sph_fluid.hpp"

#include "wall_terms.hpp"

#include "fsi/core/parallel.hpp"

#include <algorithm>
#include <cmath>

namespace fsi::sph {

template <int D> void BasicSphFluid<D>::second_half(double dt) {
  auto& f = fluid_;
  const double half = 0.5 * dt;
  std::array<double*, D> x, v;
  std::array<const double*, D> a, ap, e, we, wv, wa;
  for (int c = 0; c < D; ++c) {
    x[c] = f.x[c].data(), v[c] = f.v[c].data(), a[c] = f.a[c].data(), ap[c] = f.ap[c].data();
    e[c] = pe_[c].data(), we[c] = we_[c].data(), wv[c] = walls_.v[c].data();
    wa[c] = walls_.a[c].data();
  }
  parallel_for(owned(), [&](std::size_t i) {
    FSI_UNROLL for (int c = 0; c < D; ++c) {
      v[c][i] += a[c][i] * dt;
      x[c][i] += v[c][i] * half;
    }
  });
  particles::FieldList changed; // v_j for the continuity sums
  for (int c = 0; c < D; ++c) changed.add(f.v[c]);
  hook().update_ghosts(f.fields, changed);
  const double inv_rho0c0 = 1.0 / (options_.rho0 * options_.c0);
  const double c0 = options_.c0, four_h = 4.0 * h_;
  const double *p = f.p.data(), *vol = f.vol.data(), *wvol = walls_.vol.data();
  const std::uint32_t *pstart = pstart_.data(), *pj = pj_.data();
  const std::uint32_t *wstart = wstart_.data(), *wj = wj_.data();
  const double *pdw = pdw_.data(), *wdw = wdw_.data(), *wr = wr_.data();
  double *rho = f.rho.data(), *drho = f.drho.data();
  // Everything by value: the loop reads no member through this and no array through a reference.
  const double worst = parallel_reduce(
      owned(), 0.0,
      [=](std::size_t i) {
        const double p_i = p[i];
        double v_i[D], a_i[D], ap_i[D];
        FSI_UNROLL for (int c = 0; c < D; ++c) v_i[c] = v[c][i], a_i[c] = a[c][i],
                                               ap_i[c] = ap[c][i];
        double s = 0.0;
        // Continuity (eqs. 3, 5): rho_i sum [(v_i - v_j) . e_ij + (p_i - p_j) / (rho0 c0)] dW V_j.
        for (std::uint32_t k = pstart[i]; k < pstart[i + 1]; ++k) {
          const std::uint32_t j = pj[k];
          double dv[D], e_k[D];
          FSI_UNROLL for (int c = 0; c < D; ++c) dv[c] = v_i[c] - v[c][j], e_k[c] = e[c][k];
          const double u = dot<D>(dv, e_k);
          s += (u + (p_i - p[j]) * inv_rho0c0) * pdw[k] * vol[j];
        }
        // Walls: v_d = 2 v_w - v_i, so v_i - v_d = 2 (v_i - v_w); the pressure term with the
        // dummy pressure p_d of eq. 16 (the reference code's wall density diffusion).
        const double rho_i = rho[i];
        for (std::uint32_t k = wstart[i]; k < wstart[i + 1]; ++k) {
          const std::uint32_t w = wj[k];
          double dv[D], e_k[D], da[D];
          FSI_UNROLL for (int c = 0; c < D; ++c) dv[c] = v_i[c] - wv[c][w], e_k[c] = we[c][k],
                                                 da[c] = ap_i[c] - wa[c][w];
          const double u = dot<D>(dv, e_k);
          const double p_id = -dummy_jump<D>(rho_i, wr[k], da, e_k);
          s += (2.0 * u + p_id * inv_rho0c0) * wdw[k] * wvol[w];
        }
        drho[i] = rho[i] * s;
        rho[i] += drho[i] * half;
        // Acoustic criterion: max(c0 + |v|, sqrt(4 h |a|)).
        const double speed = std::sqrt(dot<D>(v_i, v_i)), acc = std::sqrt(dot<D>(a_i, a_i));
        return std::max(c0 + speed, std::sqrt(four_h * acc));
      },
      [](double l, double r) { return std::max(l, r); }); // NaN-safe: a NaN is caught by guard()
  dt_acoustic_ = options_.acoustic_cfl * h_ / hook().max(worst);
}

template void BasicSphFluid<2>::second_half(double);
template void BasicSphFluid<3>::second_half(double);

} // namespace fsi::sph
