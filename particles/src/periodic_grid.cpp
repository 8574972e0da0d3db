#include "particles/periodic_grid.hpp"

#include "binning.hpp"

#include <cmath>
#include <stdexcept>

namespace fsi::particles {

PeriodicGrid::PeriodicGrid(const Vec2& lo, const Vec2& hi, double cell, bool periodic_x,
                           bool periodic_y)
    : periodic_x_(periodic_x), periodic_y_(periodic_y) {
  period_ = hi - lo;
  // Periodic: floor(L / cell) cells of side L / n >= cell. Otherwise one spare cell each side.
  const auto count = [&](double length, bool periodic) {
    return periodic ? static_cast<int>(std::floor(length / cell))
                    : static_cast<int>(std::ceil(length / cell)) + 2;
  };
  nx_ = count(period_.x(), periodic_x);
  ny_ = count(period_.y(), periodic_y);
  if ((periodic_x && nx_ < 3) || (periodic_y && ny_ < 3))
    throw std::invalid_argument("PeriodicGrid: a periodic direction needs >= 3 cells");
  lo_ = Vec2(periodic_x ? lo.x() : lo.x() - cell, periodic_y ? lo.y() : lo.y() - cell);
  inv_cell_ = Vec2(periodic_x ? nx_ / period_.x() : 1.0 / cell,
                   periodic_y ? ny_ / period_.y() : 1.0 / cell);
  start_.assign(static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_) + 1, 0);
}

namespace {
/// v brought into [lo, lo + L) by one period along a periodic axis; unchanged otherwise.
double wrap(double v, double lo, double L, bool periodic) {
  if (!periodic) return v;
  if (v < lo) v += L;
  if (v >= lo + L) v -= L;
  return v;
}
} // namespace

double PeriodicGrid::wrap_x(double x) const {
  return wrap(x, lo_.x(), period_.x(), periodic_x_);
}

double PeriodicGrid::wrap_y(double y) const {
  return wrap(y, lo_.y(), period_.y(), periodic_y_);
}

int PeriodicGrid::cell_x(double x) const {
  return detail::cell_index(x, lo_.x(), inv_cell_.x(), nx_);
}

int PeriodicGrid::cell_y(double y) const {
  return detail::cell_index(y, lo_.y(), inv_cell_.y(), ny_);
}

void PeriodicGrid::bin(const double* x, const double* y, std::size_t n) {
  detail::sort_by_cell(
      n,
      [&](std::size_t i) { return static_cast<std::uint32_t>(cell_y(y[i]) * nx_ + cell_x(x[i])); },
      cell_, start_, order_);
}

} // namespace fsi::particles
