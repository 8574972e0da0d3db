#include "geometry_erp/triangle_locator.hpp"

#include "nearest_triangle.hpp"

#include "fsi/core/parallel.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fsi::erp {

namespace {
/// Upper bound on the cell count: a wide domain gets cells larger than r_e rather than a huge grid.
constexpr double max_cells = 1 << 22;
} // namespace

void TriangleHits::resize(std::size_t n) {
  triangle.resize(n);
  feature.resize(n);
  bary.resize(n);
  r.resize(n);
  x_wall.resize(n);
  n_wall.resize(n);
  v_wall.resize(n);
  a_wall.resize(n);
  crossed.resize(n);
}

std::size_t TriangleLocator::cell(int i, int j, int k) const {
  return (static_cast<std::size_t>(k) * static_cast<std::size_t>(n_[1]) +
          static_cast<std::size_t>(j)) *
             static_cast<std::size_t>(n_[0]) +
         static_cast<std::size_t>(i);
}

TriangleLocator::TriangleLocator(const TriangleWallSet& walls, double r_e)
    : walls_(&walls), r_e_(r_e) {
  update();
}

void TriangleLocator::update() {
  const auto& tri = walls_->triangles().node;
  const auto& x = walls_->nodes().x;
  const auto geometry = [&](std::size_t t) {
    return TriangleGeometry{x[static_cast<std::size_t>(tri[t][0])],
                            x[static_cast<std::size_t>(tri[t][1])],
                            x[static_cast<std::size_t>(tri[t][2])], static_cast<int>(t)};
  };
  // A triangle with a non-finite node is binned nowhere (the run's finite-value guard stops it).
  const auto finite = [](const TriangleGeometry& g) {
    return g.a.allFinite() && g.b.allFinite() && g.c.allFinite();
  };
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  bool any = false;
  for (std::size_t t = 0; t < tri.size(); ++t) {
    const TriangleGeometry g = geometry(t);
    if (!finite(g)) continue;
    any = true;
    lo = lo.cwiseMin(g.a).cwiseMin(g.b).cwiseMin(g.c);
    hi = hi.cwiseMax(g.a).cwiseMax(g.b).cwiseMax(g.c);
  }
  if (!any) lo = hi = Vec3::Zero();
  const Vec3 extent = hi - lo;
  // Cells of side r_e, grown until they number at most max_cells (flat walls included).
  const auto count = [&](double h) {
    return (std::floor(extent.x() / h) + 1.0) * (std::floor(extent.y() / h) + 1.0) *
           (std::floor(extent.z() / h) + 1.0);
  };
  h_ = r_e_;
  while (count(h_) > max_cells) h_ *= 1.25;
  lo_ = lo;
  for (int d = 0; d < 3; ++d)
    n_[static_cast<std::size_t>(d)] = static_cast<int>(extent[d] / h_) + 1;

  // Counting sort of (cell, triangle) pairs into CSR arrays; capacity is kept between updates.
  const auto cell_box = [&](const TriangleGeometry& g, std::array<int, 3>& c0,
                            std::array<int, 3>& c1) {
    const Vec3 gl = g.a.cwiseMin(g.b).cwiseMin(g.c), gh = g.a.cwiseMax(g.b).cwiseMax(g.c);
    for (std::size_t d = 0; d < 3; ++d) {
      const auto e = static_cast<Eigen::Index>(d);
      c0[d] = static_cast<int>((gl[e] - lo_[e]) / h_);
      c1[d] = std::min(static_cast<int>((gh[e] - lo_[e]) / h_), n_[d] - 1);
    }
  };
  const auto for_cells = [&](const TriangleGeometry& g, auto&& f) {
    std::array<int, 3> c0, c1;
    cell_box(g, c0, c1);
    for (int k = c0[2]; k <= c1[2]; ++k)
      for (int j = c0[1]; j <= c1[1]; ++j)
        for (int i = c0[0]; i <= c1[0]; ++i) f(cell(i, j, k));
  };
  const std::size_t cells = static_cast<std::size_t>(n_[0]) * static_cast<std::size_t>(n_[1]) *
                            static_cast<std::size_t>(n_[2]);
  cell_begin_.assign(cells + 1, 0);
  for (std::size_t t = 0; t < tri.size(); ++t) {
    const TriangleGeometry g = geometry(t);
    if (finite(g)) for_cells(g, [&](std::size_t c) { ++cell_begin_[c + 1]; });
  }
  for (std::size_t c = 0; c < cells; ++c) cell_begin_[c + 1] += cell_begin_[c];
  cell_triangle_.resize(static_cast<std::size_t>(cell_begin_[cells]));
  for (std::size_t t = 0; t < tri.size(); ++t) {
    const TriangleGeometry g = geometry(t);
    if (finite(g))
      for_cells(g, [&](std::size_t c) {
        cell_triangle_[static_cast<std::size_t>(cell_begin_[c]++)] = g;
      });
  }
  // The fill pass advanced each offset to the next cell's start: shift back.
  for (std::size_t c = cells; c > 0; --c) cell_begin_[c] = cell_begin_[c - 1];
  cell_begin_[0] = 0;
}

void TriangleLocator::locate(const QueryPoints3& points, TriangleHits& hits) const {
  const std::size_t n = points.size();
  hits.resize(n);
  parallel_for_balanced(n, [&](std::size_t i) {
    const Vec3 p = points(i);
    detail::NearestTriangle best;
    best.d2 = r_e_ * r_e_;
    const Vec3 f = ((p - lo_) / h_).array().floor();
    // Outside the grid by more than one cell (or NaN): no triangle within r_e <= h.
    const bool near = (f.array() >= -1.0).all() && f[0] <= n_[0] && f[1] <= n_[1] && f[2] <= n_[2];
    if (near) {
      const std::array<int, 3> c{static_cast<int>(f[0]), static_cast<int>(f[1]),
                                 static_cast<int>(f[2])};
      const auto scan = [&](int ci, int cj, int ck) {
        const std::size_t cell = this->cell(ci, cj, ck);
        for (int k = cell_begin_[cell]; k < cell_begin_[cell + 1]; ++k)
          detail::consider_triangle(cell_triangle_[static_cast<std::size_t>(k)], p, best);
      };
      const bool own =
          c[0] >= 0 && c[0] < n_[0] && c[1] >= 0 && c[1] < n_[1] && c[2] >= 0 && c[2] < n_[2];
      if (own) scan(c[0], c[1], c[2]);
      // Then a neighbour only if its box (grown by a rounding margin) is not farther than the
      // best triangle so far: the nearest point of a triangle lies in a cell it is binned in.
      const double margin = 1e-9 * h_;
      for (int k = std::max(c[2] - 1, 0); k <= std::min(c[2] + 1, n_[2] - 1); ++k)
        for (int j = std::max(c[1] - 1, 0); j <= std::min(c[1] + 1, n_[1] - 1); ++j)
          for (int ci = std::max(c[0] - 1, 0); ci <= std::min(c[0] + 1, n_[0] - 1); ++ci) {
            const std::size_t cell = this->cell(ci, j, k);
            if ((own && ci == c[0] && j == c[1] && k == c[2]) ||
                cell_begin_[cell] == cell_begin_[cell + 1])
              continue;
            const Vec3 box_lo = lo_ + h_ * Vec3(ci, j, k) - Vec3::Constant(margin);
            const Vec3 box_hi = box_lo + Vec3::Constant(h_ + 2.0 * margin);
            const Vec3 gap = (box_lo - p).cwiseMax(p - box_hi).cwiseMax(0.0);
            if (gap.squaredNorm() <= best.d2) scan(ci, j, k);
          }
    }
    detail::write_triangle_hit(*walls_, r_e_, p, best, hits, i);
  });
}

} // namespace fsi::erp
