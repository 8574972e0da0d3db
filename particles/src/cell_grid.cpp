#include "particles/cell_grid.hpp"

#include "binning.hpp"

#include <cmath>

namespace fsi::particles {

CellGrid::CellGrid(const Vec2& lo, const Vec2& hi, double h)
    : lo_(lo - Vec2(h, h)), h_(h), inv_h_(1.0 / h),
      nx_(static_cast<int>(std::ceil((hi.x() - lo.x()) / h)) + 3),
      ny_(static_cast<int>(std::ceil((hi.y() - lo.y()) / h)) + 3) {
  start_.assign(static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_) + 1, 0);
}

int CellGrid::cell_x(double x) const {
  return detail::cell_index(x, lo_.x(), inv_h_, nx_);
}

int CellGrid::cell_y(double y) const {
  return detail::cell_index(y, lo_.y(), inv_h_, ny_);
}

void CellGrid::bin(const double* x, const double* y, std::size_t n) {
  detail::sort_by_cell(
      n,
      [&](std::size_t i) { return static_cast<std::uint32_t>(cell_y(y[i]) * nx_ + cell_x(x[i])); },
      cell_, start_, order_);
}

} // namespace fsi::particles
