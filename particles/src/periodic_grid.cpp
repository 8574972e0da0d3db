#include "particles/periodic_grid.hpp"

#include "fsi/core/parallel.hpp"

#include <algorithm>
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

double PeriodicGrid::wrap_x(double x) const {
  if (!periodic_x_) return x;
  const double L = period_.x();
  if (x < lo_.x()) x += L;
  if (x >= lo_.x() + L) x -= L;
  return x;
}

double PeriodicGrid::wrap_y(double y) const {
  if (!periodic_y_) return y;
  const double L = period_.y();
  if (y < lo_.y()) y += L;
  if (y >= lo_.y() + L) y -= L;
  return y;
}

int PeriodicGrid::cell_x(double x) const {
  const double c = std::floor((x - lo_.x()) * inv_cell_.x());
  return static_cast<int>(std::clamp(c, 0.0, static_cast<double>(nx_ - 1)));
}

int PeriodicGrid::cell_y(double y) const {
  const double c = std::floor((y - lo_.y()) * inv_cell_.y());
  return static_cast<int>(std::clamp(c, 0.0, static_cast<double>(ny_ - 1)));
}

void PeriodicGrid::bin(const double* x, const double* y, std::size_t n) {
  cell_.resize(n);
  order_.resize(n);
  parallel_for(n, [&](std::size_t i) {
    cell_[i] = static_cast<std::uint32_t>(cell_y(y[i]) * nx_ + cell_x(x[i]));
  });
  std::fill(start_.begin(), start_.end(), 0u);
  for (std::size_t i = 0; i < n; ++i) ++start_[cell_[i] + 1];
  for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
  for (std::size_t i = 0; i < n; ++i) cell_[i] = start_[cell_[i]]++; // slot of particle i
  for (std::size_t i = 0; i < n; ++i) order_[cell_[i]] = static_cast<std::uint32_t>(i);
  for (std::size_t c = start_.size() - 1; c > 0; --c) start_[c] = start_[c - 1];
  start_[0] = 0;
}

} // namespace fsi::particles
