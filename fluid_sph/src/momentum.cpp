// The acoustic step's first half: density and position by dt/2, pressure by the equation of
// state (eq. 2), and the momentum equation (eqs. 3-5, 18, 20) with the Riemann dissipation between
// fluid pairs and the wall terms (eqs. 15-17).
#include "fluid_sph/sph_fluid.hpp"

#include "wall_terms.hpp"

#include "fsi/core/parallel.hpp"

namespace fsi::sph {

template <int D> void BasicSphFluid<D>::first_half(double dt) {
  auto& f = fluid_;
  const double half = 0.5 * dt, c2 = options_.c0 * options_.c0, rho0 = options_.rho0;
  // The component arrays as raw pointers before the loops (D known at compile time).
  std::array<double*, D> x, v, a;
  std::array<const double*, D> ap, e, wv, wa, wn;
  std::array<const double*, S> b;
  for (int c = 0; c < D; ++c) {
    x[c] = f.x[c].data(), v[c] = f.v[c].data(), a[c] = f.a[c].data(), ap[c] = f.ap[c].data();
    e[c] = pe_[c].data(), wv[c] = walls_.v[c].data(), wa[c] = walls_.a[c].data();
    wn[c] = walls_.n[c].data();
  }
  for (int s = 0; s < S; ++s) b[s] = f.b[s]->data();
  parallel_for(owned(), [&](std::size_t i) {
    f.rho[i] += f.drho[i] * half;
    f.p[i] = c2 * (f.rho[i] - rho0); // eq. 2
    for (int c = 0; c < D; ++c) x[c][i] += v[c][i] * half;
  });
  particles::FieldList changed(f.p); // p_j for the pair sums; v_j too after damping
  for (int c = 0; c < D; ++c) changed.add(f.v[c]);
  hook().update_ghosts(f.fields, changed);
  const double rho0c0 = rho0 * options_.c0, inv_c0 = 1.0 / options_.c0, inv_m = 1.0 / mass_;
  const bool lim = options_.riemann_limiter;
  const double rho0c0_pairs = options_.pair_dissipation ? rho0c0 : 0.0;
  const double *p = f.p.data(), *vol = f.vol.data(), *wvol = walls_.vol.data(), *rho = f.rho.data();
  const std::uint32_t *pstart = pstart_.data(), *pj = pj_.data();
  const std::uint32_t *wstart = wstart_.data(), *wj = wj_.data();
  const double *pdw = pdw_.data(), *wdw = wdw_.data(), *wr = wr_.data();
  std::array<const double*, D> we;
  for (int c = 0; c < D; ++c) we[c] = we_[c].data();
  // Everything by value: the loop reads no member through this and no array through a reference.
  parallel_for(owned(), [=](std::size_t i) {
    const double p_i = p[i];
    double v_i[D], b_i[S], F[D] = {};
    FSI_UNROLL for (int c = 0; c < D; ++c) v_i[c] = v[c][i];
    FSI_UNROLL for (int s = 0; s < S; ++s) b_i[s] = b[s][i];
    for (std::uint32_t k = pstart[i]; k < pstart[i + 1]; ++k) {
      const std::uint32_t j = pj[k];
      const double dWV = pdw[k] * vol[j], p_j = p[j];
      double g[D], b_j[S], dv[D], e_k[D];
      FSI_UNROLL for (int s = 0; s < S; ++s) b_j[s] = b[s][j];
      FSI_UNROLL for (int c = 0; c < D; ++c) e_k[c] = e[c][k], g[c] = dWV * e_k[c],
                                             dv[c] = v_i[c] - v[c][j];
      // (p_i B_j + p_j B_i) grad W_ij V_j (eqs. 18, 20).
      FSI_UNROLL for (int c = 0; c < D; ++c) F[c] -=
          p_i * sym_row<D>(b_j, c, g) + p_j * sym_row<D>(b_i, c, g);
      // Riemann dissipation: -2 (P* - p_bar) grad W = beta rho0 c0 u grad W (eq. 5).
      const double u = dot<D>(dv, e_k);
      const double d = rho0c0_pairs * limiter(u, inv_c0, lim) * u;
      FSI_UNROLL for (int c = 0; c < D; ++c) F[c] += d * g[c];
    }
    // Walls (eqs. 15-17): dummy pressure p_d = p_i + rho_i r max(0, (a_prior - a_w) . (-e_ia)).
    const double rho_i = rho[i];
    for (std::uint32_t k = wstart[i]; k < wstart[i + 1]; ++k) {
      const std::uint32_t w = wj[k];
      WallPair<D> q{p_i, rho_i, wr[k], {}, {}, wdw[k] * wvol[w], b_i, {}, {}, rho0c0, inv_c0, lim};
      FSI_UNROLL for (int c = 0; c < D; ++c) {
        q.da[c] = ap[c][i] - wa[c][w], q.e[c] = we[c][k];
        q.dv[c] = v_i[c] - wv[c][w], q.n[c] = wn[c][w];
      }
      const auto t = wall_term(q);
      FSI_UNROLL for (int c = 0; c < D; ++c) F[c] += t[c];
    }
    const double s = vol[i] * inv_m;
    FSI_UNROLL for (int c = 0; c < D; ++c) a[c][i] = F[c] * s + ap[c][i];
  });
}

template void BasicSphFluid<2>::first_half(double);
template void BasicSphFluid<3>::first_half(double);

} // namespace fsi::sph
