#include "particles/box_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fsi::particles {

namespace {
constexpr double max_cells = 1 << 22;

bool finite(const Box3d& b) {
  return b.lo.allFinite() && b.hi.allFinite();
}
} // namespace

void BoxGrid::build(std::span<const Box3d> boxes, double min_cell) {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  bool any = false;
  for (const Box3d& b : boxes) {
    if (!finite(b)) continue;
    any = true;
    lo = lo.cwiseMin(b.lo), hi = hi.cwiseMax(b.hi);
  }
  if (!any) lo = hi = Vec3::Zero();
  const Vec3 extent = hi - lo;
  const auto count = [&](double h) {
    return (std::floor(extent.x() / h) + 1.0) * (std::floor(extent.y() / h) + 1.0) *
           (std::floor(extent.z() / h) + 1.0);
  };
  h_ = min_cell;
  while (count(h_) > max_cells) h_ *= 1.25;
  lo_ = lo;
  for (int d = 0; d < 3; ++d)
    n_[static_cast<std::size_t>(d)] = static_cast<int>(extent[d] / h_) + 1;

  const auto for_cells = [&](const Box3d& b, auto&& f) {
    std::array<int, 3> c0, c1;
    for (std::size_t d = 0; d < 3; ++d) {
      const auto e = static_cast<Eigen::Index>(d);
      c0[d] = static_cast<int>((b.lo[e] - lo_[e]) / h_);
      c1[d] = std::min(static_cast<int>((b.hi[e] - lo_[e]) / h_), n_[d] - 1);
    }
    for (int k = c0[2]; k <= c1[2]; ++k)
      for (int j = c0[1]; j <= c1[1]; ++j)
        for (int i = c0[0]; i <= c1[0]; ++i) f(cell(i, j, k));
  };
  const std::size_t cells = static_cast<std::size_t>(n_[0]) * static_cast<std::size_t>(n_[1]) *
                            static_cast<std::size_t>(n_[2]);
  begin_.assign(cells + 1, 0);
  for (const Box3d& b : boxes)
    if (finite(b)) for_cells(b, [&](std::size_t c) { ++begin_[c + 1]; });
  for (std::size_t c = 0; c < cells; ++c) begin_[c + 1] += begin_[c];
  entry_.resize(static_cast<std::size_t>(begin_[cells]));
  for (std::size_t t = 0; t < boxes.size(); ++t)
    if (finite(boxes[t]))
      for_cells(boxes[t], [&](std::size_t c) {
        entry_[static_cast<std::size_t>(begin_[c]++)] = static_cast<int>(t);
      });
  // The fill pass advanced each offset to the next cell's start: shift back.
  for (std::size_t c = cells; c > 0; --c) begin_[c] = begin_[c - 1];
  begin_[0] = 0;
}

void BoxGrid::overlapping(const Vec3& lo, const Vec3& hi, std::vector<int>& out) const {
  out.clear();
  std::array<int, 3> c0, c1;
  for (std::size_t d = 0; d < 3; ++d) {
    const auto e = static_cast<Eigen::Index>(d);
    const double a = std::floor((lo[e] - lo_[e]) / h_), b = std::floor((hi[e] - lo_[e]) / h_);
    if (!(b >= 0.0 && a < n_[d])) return; // outside the grid along d (or NaN)
    c0[d] = static_cast<int>(std::max(a, 0.0));
    c1[d] = static_cast<int>(std::min(b, n_[d] - 1.0));
  }
  for (int k = c0[2]; k <= c1[2]; ++k)
    for (int j = c0[1]; j <= c1[1]; ++j)
      for (int i = c0[0]; i <= c1[0]; ++i) {
        const std::size_t c = cell(i, j, k);
        out.insert(out.end(), entry_.begin() + begin_[c], entry_.begin() + begin_[c + 1]);
      }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

} // namespace fsi::particles
