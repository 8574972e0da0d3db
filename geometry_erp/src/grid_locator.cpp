#include "geometry_erp/grid_locator.hpp"

#include "nearest_segment.hpp"

#include <cmath>

namespace fsi::erp {

namespace {
/// Upper bound on the cell count: a wide domain gets cells larger than r_e rather than a huge grid.
constexpr double max_cells = 1 << 22;
} // namespace

GridLocator::GridLocator(const WallSet& walls, double r_e) : WallLocator(walls, r_e) {
  update();
}

void GridLocator::update() {
  const WallSet& walls = *walls_;
  const auto& seg = walls.segments().node;
  const auto& x = walls.nodes().x;
  // A segment with a non-finite node is binned nowhere: no particle can be near it, and the run's
  // finite-value guard stops the run after the step (the grid stays finite).
  const auto finite = [&](const std::array<int, 2>& ab) {
    return x[static_cast<std::size_t>(ab[0])].allFinite() &&
           x[static_cast<std::size_t>(ab[1])].allFinite();
  };
  Vec2 lo = Vec2::Constant(std::numeric_limits<double>::infinity());
  Vec2 hi = -lo;
  bool any = false;
  for (const auto& ab : seg) {
    if (!finite(ab)) continue;
    any = true;
    lo = lo.cwiseMin(x[static_cast<std::size_t>(ab[0])])
             .cwiseMin(x[static_cast<std::size_t>(ab[1])]);
    hi = hi.cwiseMax(x[static_cast<std::size_t>(ab[0])])
             .cwiseMax(x[static_cast<std::size_t>(ab[1])]);
  }
  if (!any) lo = hi = Vec2::Zero();
  const Vec2 extent = hi - lo;
  h_ = std::max(r_e_, std::sqrt(extent.x() * extent.y() / max_cells));
  h_ = std::max({h_, extent.x() / max_cells, extent.y() / max_cells});
  lo_ = lo;
  nx_ = static_cast<int>(extent.x() / h_) + 1;
  ny_ = static_cast<int>(extent.y() / h_) + 1;

  // Counting sort of (cell, segment) pairs into CSR arrays; capacity is kept between updates.
  const auto cell_range = [&](const std::array<int, 2>& ab, int& i0, int& i1, int& j0, int& j1) {
    const Vec2& xa = x[static_cast<std::size_t>(ab[0])];
    const Vec2& xb = x[static_cast<std::size_t>(ab[1])];
    i0 = static_cast<int>((std::min(xa.x(), xb.x()) - lo_.x()) / h_);
    i1 = std::min(static_cast<int>((std::max(xa.x(), xb.x()) - lo_.x()) / h_), nx_ - 1);
    j0 = static_cast<int>((std::min(xa.y(), xb.y()) - lo_.y()) / h_);
    j1 = std::min(static_cast<int>((std::max(xa.y(), xb.y()) - lo_.y()) / h_), ny_ - 1);
  };
  const std::size_t cells = static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_);
  cell_begin_.assign(cells + 1, 0);
  int i0, i1, j0, j1;
  for (const auto& ab : seg) {
    if (!finite(ab)) continue;
    cell_range(ab, i0, i1, j0, j1);
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) ++cell_begin_[static_cast<std::size_t>(j * nx_ + i) + 1];
  }
  for (std::size_t c = 0; c < cells; ++c) cell_begin_[c + 1] += cell_begin_[c];
  cell_segment_.resize(static_cast<std::size_t>(cell_begin_[cells]));
  for (std::size_t s = 0; s < seg.size(); ++s) {
    if (!finite(seg[s])) continue;
    const SegmentGeometry geometry = detail::segment_geometry(walls, static_cast<int>(s));
    cell_range(seg[s], i0, i1, j0, j1);
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) {
        int& next = cell_begin_[static_cast<std::size_t>(j * nx_ + i)];
        cell_segment_[static_cast<std::size_t>(next++)] = geometry;
      }
  }
  // The fill pass advanced each offset to the next cell's start: shift back.
  for (std::size_t c = cells; c > 0; --c) cell_begin_[c] = cell_begin_[c - 1];
  cell_begin_[0] = 0;
}

void GridLocator::locate(const QueryPoints& points, WallHits& hits) const {
  const WallSet& walls = *walls_;
  detail::batch_query(
      walls, r_e_, corner_faces_, points.size(), points,
      [&](const Vec2& p, const double& bound, auto&& consider) {
        const double fi = std::floor((p.x() - lo_.x()) / h_),
                     fj = std::floor((p.y() - lo_.y()) / h_);
        // Outside the grid by more than one cell (or NaN): no segment within r_e <= h.
        if (!(fi >= -1.0 && fi <= nx_ && fj >= -1.0 && fj <= ny_)) return;
        const int ci = static_cast<int>(fi), cj = static_cast<int>(fj);
        const auto scan = [&](int i, int j) {
          const auto c = static_cast<std::size_t>(j * nx_ + i);
          for (int k = cell_begin_[c]; k < cell_begin_[c + 1]; ++k)
            consider(cell_segment_[static_cast<std::size_t>(k)]);
        };
        // Own cell first; then a neighbour only if its box (grown by a rounding margin) is not
        // farther than the best segment so far: the nearest point of a segment lies in one of
        // the cells it is binned in.
        const bool own = ci >= 0 && ci < nx_ && cj >= 0 && cj < ny_;
        if (own) scan(ci, cj);
        const double margin = 1e-9 * h_;
        for (int j = std::max(cj - 1, 0); j <= std::min(cj + 1, ny_ - 1); ++j)
          for (int i = std::max(ci - 1, 0); i <= std::min(ci + 1, nx_ - 1); ++i) {
            const auto c = static_cast<std::size_t>(j * nx_ + i);
            if ((own && i == ci && j == cj) || cell_begin_[c] == cell_begin_[c + 1]) continue;
            const double x0 = lo_.x() + i * h_ - margin, y0 = lo_.y() + j * h_ - margin;
            const double dx = std::max(std::max(x0 - p.x(), p.x() - (x0 + h_ + 2.0 * margin)), 0.0);
            const double dy = std::max(std::max(y0 - p.y(), p.y() - (y0 + h_ + 2.0 * margin)), 0.0);
            if (dx * dx + dy * dy <= bound) scan(i, j);
          }
      },
      hits);
}

} // namespace fsi::erp
