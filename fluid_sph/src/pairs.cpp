// The neighbour pairs of an advection step (fluid-fluid and fluid-wall, from the build positions,
// e_ij, dW_ij and r_ij per pair) and the through-a-wall guard.
#include "fluid_sph/sph_fluid.hpp"

#include "shared.hpp"

#include "fsi/core/error.hpp"
#include "fsi/core/parallel.hpp"

#include <algorithm>
#include <cmath>

namespace fsi::sph {

namespace {

/// Neighbour j at d = x_i - x_j into slot k of a pair set: e_ij, dW_ij, r_ij.
template <int D, class K>
inline void store_pair(std::uint32_t k, std::uint32_t j, const double* d, const K& kernel,
                       std::vector<std::uint32_t>& js, std::array<std::vector<double>, D>& e,
                       std::vector<double>& dw, std::vector<double>& rs) {
  const double r = std::sqrt(dot<D>(d, d));
  js[k] = j;
  FSI_UNROLL for (int c = 0; c < D; ++c) e[c][k] = d[c] / r;
  dw[k] = kernel.dW(r);
  rs[k] = r;
}

/// |r e x n|, the distance from wall point a's normal line (through a) of a particle at r e from
/// it: |r (e_x n_y - e_y n_x)| in 2-D.
template <int D> inline double off_normal(double r, const double* e, const double* n) {
  if constexpr (D == 2) {
    return std::abs(r * (e[0] * n[1] - e[1] * n[0]));
  } else {
    const double c0 = e[1] * n[2] - e[2] * n[1], c1 = e[2] * n[0] - e[0] * n[2];
    const double c2 = e[0] * n[1] - e[1] * n[0];
    return r * std::sqrt(c0 * c0 + c1 * c1 + c2 * c2);
  }
}

} // namespace

template <int D> void BasicSphFluid<D>::build_pairs(bool guard) {
  auto& f = fluid_;
  // Pairs of the owned particles; neighbours among owned and ghosts.
  const std::size_t n = owned(), nw = walls_.size();
  grid_.bin(f.xb.coords(), f.size());
  wall_grid_.bin(walls_.xb.coords(), nw);
  const double cut2 = kernel_.cutoff() * kernel_.cutoff();
  const particles::Coords<D> xb = f.xb.coords(), wxb = walls_.xb.coords();
  // d = x_i - x_j - s (the image shift s of a periodic neighbour) and |d|^2.
  const auto offset = [](const Vec& x_i, const double* x_j, const std::array<double, D>& s,
                         double* d) {
    FSI_UNROLL for (int c = 0; c < D; ++c) d[c] = x_i[c] - x_j[c] - s[c];
    return dot<D>(d, d);
  };
  const auto at = [](const particles::Coords<D>& x, std::size_t j, double* out) {
    FSI_UNROLL for (int c = 0; c < D; ++c) out[c] = x[c][j];
  };
  count_.resize(2 * n);
  parallel_for_balanced(n, [&](std::size_t i) {
    Vec x_i;
    FSI_UNROLL for (int c = 0; c < D; ++c) x_i[c] = xb[c][i];
    std::uint32_t c = 0, cw = 0;
    grid_.for_each_near(x_i, [&](std::uint32_t j, const std::array<double, D>& s) {
      double d[D], x_j[D];
      at(xb, j, x_j);
      const double r2 = offset(x_i, x_j, s, d);
      if (j != i && r2 < cut2 && r2 > 0.0) ++c;
    });
    wall_grid_.for_each_near(x_i, [&](std::uint32_t a, const std::array<double, D>& s) {
      double d[D], x_a[D];
      at(wxb, a, x_a);
      const double r2 = offset(x_i, x_a, s, d);
      if (r2 < cut2 && r2 > 0.0) ++cw;
    });
    count_[i] = c;
    count_[n + i] = cw;
  });
  pstart_.resize(n + 1);
  wstart_.resize(n + 1);
  pstart_[0] = wstart_[0] = 0;
  for (std::size_t i = 0; i < n; ++i) {
    pstart_[i + 1] = pstart_[i] + count_[i];
    wstart_[i + 1] = wstart_[i] + count_[n + i];
  }
  // Grow only (with headroom): no allocation in the usual advection step.
  if (pstart_[n] > pj_.size()) {
    const std::size_t m = pstart_[n] + pstart_[n] / 8 + 16;
    pj_.resize(m), pdw_.resize(m), pr_.resize(m);
    for (auto& e : pe_) e.resize(m);
  }
  if (wstart_[n] > wj_.size()) {
    const std::size_t m = wstart_[n] + wstart_[n] / 8 + 16;
    wj_.resize(m), wdw_.resize(m), wr_.resize(m);
    for (auto& e : we_) e.resize(m);
  }
  // Fill, in the same visiting order, then the through-a-wall guard (issue 20, Antoci's gate):
  // from wall point a, with p = (x_i - x_a) . n_a - depth_a and q = |(x_i - x_a) x n_a|, the
  // particle's signed distance to the wall surface is s_a = p on a face, the same from every
  // point of a flat face (all layers); on the bisector of a convex corner whose faces' normals
  // are 2 phi apart, with corner_a = sin(phi), s_a = cos(phi) p + sin(phi) q, the larger of
  // the signed distances to the two faces' lines through the corner. A particle is behind the
  // walls when s_a < -dp/2 (the first layer's plane, the guard's tolerance) for the nearest
  // point AND every point within 1.5 dp more (the nearest's lattice neighbours, dp and
  // sqrt(2) dp away): the intersection of half-planes, the inside test at a convex corner,
  // where a particle beside a thin body's end is behind the end face's plane but in front of
  // the side face. Given up: a particle through a face near a concave corner is caught only
  // once it is out of the other face's range (about a dp from it); acceptable for a guard,
  // which only has to stop a run whose particles get well through a wall. At a flat wall it
  // flags what the nearest point's plane did, and a particle past the first layer too. Where the
  // caller gave the nearest point's group an exact surface (the constructor's distances), a
  // particle is flagged only if that surface puts it behind the tolerance too: the end face of a
  // body 2 dp thick may have no point of its own (its row nearer the side faces), and a particle
  // above that end is then behind both sides' planes.
  const double reach = 1.5 * options_.dp, tolerance = -0.5 * options_.dp;
  const std::size_t behind = parallel_reduce_balanced(
      n, none,
      [&](std::size_t i) {
        Vec x_i;
        FSI_UNROLL for (int c = 0; c < D; ++c) x_i[c] = xb[c][i];
        std::uint32_t k = pstart_[i];
        grid_.for_each_near(x_i, [&](std::uint32_t j, const std::array<double, D>& s) {
          double d[D], x_j[D];
          at(xb, j, x_j);
          const double r2 = offset(x_i, x_j, s, d);
          if (j == i || r2 >= cut2 || r2 <= 0.0) return;
          store_pair<D>(k++, j, d, kernel_, pj_, pe_, pdw_, pr_);
        });
        const std::uint32_t kw0 = wstart_[i];
        std::uint32_t kw = kw0;
        double nearest = cut2;
        std::uint32_t a_nearest = 0;
        wall_grid_.for_each_near(x_i, [&](std::uint32_t a, const std::array<double, D>& s) {
          double d[D], x_a[D];
          at(wxb, a, x_a);
          const double r2 = offset(x_i, x_a, s, d);
          if (r2 >= cut2 || r2 <= 0.0) return;
          store_pair<D>(kw++, a, d, kernel_, wj_, we_, wdw_, wr_);
          if (r2 < nearest) nearest = r2, a_nearest = a;
        });
        if (!guard) return none;
        const double within = std::sqrt(nearest) + reach;
        for (std::uint32_t k = kw0; k < kw; ++k) {
          if (wr_[k] > within) continue;
          const std::uint32_t a = wj_[k];
          double e_k[D], n_a[D];
          FSI_UNROLL for (int c = 0; c < D; ++c) e_k[c] = we_[c][k], n_a[c] = walls_.n[c][a];
          const double sine = walls_.corner[a];
          const double p = wr_[k] * dot<D>(e_k, n_a) - walls_.depth[a];
          const double q = off_normal<D>(wr_[k], e_k, n_a);
          if (std::sqrt(1.0 - sine * sine) * p + sine * q >= tolerance) return none;
        }
        if (kw == kw0) return none;
        // The group's exact surface, where the caller gave it (at the positions of the pairs).
        const std::size_t g = walls_.group[a_nearest];
        if (g < distances_.size() && distances_[g] && distances_[g](x_i) >= tolerance) return none;
        return i;
      },
      [](std::size_t a, std::size_t b) { return std::min(a, b); });
  if (behind != none) // decomposed: every process throws at agree()
    hook().fail("fluid_sph: behind the first wall layer (through a wall): " +
                where(behind, step_, t_));
  hook().agree();
}

template void BasicSphFluid<2>::build_pairs(bool);
template void BasicSphFluid<3>::build_pairs(bool);

} // namespace fsi::sph
