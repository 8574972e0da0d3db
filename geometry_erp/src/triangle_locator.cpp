#include "geometry_erp/triangle_locator.hpp"

#include "nearest_triangle.hpp"

#include "fsi/core/fresh_resize.hpp"
#include "fsi/core/parallel.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fsi::erp {

void TriangleHits::resize(std::size_t n) {
  fresh_resize(triangle, n);
  fresh_resize(feature, n);
  fresh_resize(bary, n);
  fresh_resize(r, n);
  fresh_resize(x_wall, n);
  fresh_resize(n_wall, n);
  fresh_resize(v_wall, n);
  fresh_resize(a_wall, n);
  fresh_resize(crossed, n);
}

TriangleLocator::TriangleLocator(const TriangleWallSet& walls, double r_e)
    : walls_(&walls), r_e_(r_e) {
  update();
}

TriangleGeometry TriangleLocator::geometry(std::size_t t) const {
  const auto& abc = walls_->triangles().node[t];
  const auto& x = walls_->nodes().x;
  return TriangleGeometry{x[static_cast<std::size_t>(abc[0])], x[static_cast<std::size_t>(abc[1])],
                          x[static_cast<std::size_t>(abc[2])], static_cast<int>(t)};
}

void TriangleLocator::update() {
  const auto& tri = walls_->triangles().node;
  // A triangle with a non-finite node is binned nowhere (the run's finite-value guard stops it).
  boxes_.resize(tri.size());
  for (std::size_t t = 0; t < tri.size(); ++t) {
    const TriangleGeometry g = geometry(t);
    boxes_[t] =
        g.a.allFinite() && g.b.allFinite() && g.c.allFinite()
            ? particles::Box3d{g.a.cwiseMin(g.b).cwiseMin(g.c), g.a.cwiseMax(g.b).cwiseMax(g.c)}
            : particles::Box3d{Vec3::Constant(std::nan("")), Vec3::Constant(std::nan(""))};
  }
  // Cells of side r_e (or larger: at most 2^22 of them), each triangle with its geometry.
  grid_.build(boxes_, r_e_);
  const auto& entry = grid_.entries();
  cell_triangle_.resize(entry.size());
  for (std::size_t k = 0; k < entry.size(); ++k)
    cell_triangle_[k] = geometry(static_cast<std::size_t>(entry[k]));
  has_convex_edges_ = find_convex_edge();
}

void TriangleLocator::locate(const QueryPoints3& points, TriangleHits& hits) const {
  const std::size_t n = points.size();
  const Vec3& origin = grid_.origin();
  const double h = grid_.cell_size();
  const auto& dims = grid_.dims();
  hits.resize(n);
  parallel_for_balanced(n, [&](std::size_t i) {
    const Vec3 p = points(i);
    detail::NearestTriangle best;
    best.d2 = r_e_ * r_e_;
    const Vec3 f = ((p - origin) / h).array().floor();
    // Outside the grid by more than one cell (or NaN): no triangle within r_e <= h.
    const bool near =
        (f.array() >= -1.0).all() && f[0] <= dims[0] && f[1] <= dims[1] && f[2] <= dims[2];
    if (near) {
      const std::array<int, 3> c{static_cast<int>(f[0]), static_cast<int>(f[1]),
                                 static_cast<int>(f[2])};
      const auto scan = [&](int ci, int cj, int ck) {
        const std::size_t cell = grid_.cell(ci, cj, ck);
        for (int k = grid_.begin(cell); k < grid_.begin(cell + 1); ++k)
          detail::consider_triangle(cell_triangle_[static_cast<std::size_t>(k)], p, best);
      };
      const bool own =
          c[0] >= 0 && c[0] < dims[0] && c[1] >= 0 && c[1] < dims[1] && c[2] >= 0 && c[2] < dims[2];
      if (own) scan(c[0], c[1], c[2]);
      // Then a neighbour only if its box (grown by a rounding margin) is not farther than the
      // best triangle so far: the nearest point of a triangle lies in a cell it is binned in.
      const double margin = 1e-9 * h;
      for (int k = std::max(c[2] - 1, 0); k <= std::min(c[2] + 1, dims[2] - 1); ++k)
        for (int j = std::max(c[1] - 1, 0); j <= std::min(c[1] + 1, dims[1] - 1); ++j)
          for (int ci = std::max(c[0] - 1, 0); ci <= std::min(c[0] + 1, dims[0] - 1); ++ci) {
            const std::size_t cell = grid_.cell(ci, j, k);
            if ((own && ci == c[0] && j == c[1] && k == c[2]) ||
                grid_.begin(cell) == grid_.begin(cell + 1))
              continue;
            const Vec3 box_lo = origin + h * Vec3(ci, j, k) - Vec3::Constant(margin);
            const Vec3 box_hi = box_lo + Vec3::Constant(h + 2.0 * margin);
            const Vec3 gap = (box_lo - p).cwiseMax(p - box_hi).cwiseMax(0.0);
            if (gap.squaredNorm() <= best.d2) scan(ci, j, k);
          }
    }
    detail::write_triangle_hit(*walls_, r_e_, p, best, hits, i);
  });
}

} // namespace fsi::erp
