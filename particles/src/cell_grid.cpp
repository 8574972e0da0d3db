#include "particles/cell_grid.hpp"

#include "fsi/core/parallel.hpp"

#include <algorithm>
#include <cmath>

namespace fsi::particles {

CellGrid::CellGrid(const Vec2& lo, const Vec2& hi, double h)
    : lo_(lo - Vec2(h, h)), h_(h), inv_h_(1.0 / h),
      nx_(static_cast<int>(std::ceil((hi.x() - lo.x()) / h)) + 3),
      ny_(static_cast<int>(std::ceil((hi.y() - lo.y()) / h)) + 3) {
  start_.assign(static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_) + 1, 0);
}

int CellGrid::cell_x(double x) const {
  const double c = std::floor((x - lo_.x()) * inv_h_);
  return static_cast<int>(std::clamp(c, 0.0, static_cast<double>(nx_ - 1)));
}

int CellGrid::cell_y(double y) const {
  const double c = std::floor((y - lo_.y()) * inv_h_);
  return static_cast<int>(std::clamp(c, 0.0, static_cast<double>(ny_ - 1)));
}

void CellGrid::bin(const double* x, const double* y, std::size_t n) {
  cell_.resize(n);
  order_.resize(n);
  parallel_for(n, [&](std::size_t i) {
    cell_[i] = static_cast<std::uint32_t>(cell_y(y[i]) * nx_ + cell_x(x[i]));
  });
  std::fill(start_.begin(), start_.end(), 0u);
  for (std::size_t i = 0; i < n; ++i) ++start_[cell_[i] + 1];
  for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
  // Stable scatter: within a cell, particles keep their index order (deterministic).
  std::vector<std::uint32_t>& next = cell_; // reuse: cell_ is no longer needed after this pass
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t c = next[i];
    next[i] = start_[c]++; // position of particle i in order_
  }
  for (std::size_t i = 0; i < n; ++i) order_[next[i]] = static_cast<std::uint32_t>(i);
  // start_ was advanced to the ends of the cells: shift back by one cell.
  for (std::size_t c = start_.size() - 1; c > 0; --c) start_[c] = start_[c - 1];
  start_[0] = 0;
}

} // namespace fsi::particles
