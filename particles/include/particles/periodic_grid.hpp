#pragma once
// Cell-linked list with optional periodic directions: particles binned by a counting sort into
// cells of side >= `cell` over [lo, hi); in a periodic direction the cells tile the period exactly
// and the 3 x 3 block wraps, each neighbour coming with the image shift to add to its position.
// Non-periodic directions clamp to the edge cells (as CellGrid). Needs >= 3 cells along a periodic
// direction (a particle is then found at most once around any point).
#include "fsi/core/types.hpp"

#include <cstdint>
#include <vector>

namespace fsi::particles {

class PeriodicGrid {
public:
  PeriodicGrid() = default;
  /// Throws std::invalid_argument if a periodic direction holds fewer than 3 cells.
  PeriodicGrid(const Vec2& lo, const Vec2& hi, double cell, bool periodic_x, bool periodic_y);

  /// Bins n particles; cell c then holds order()[start(c) .. start(c+1)) in index order (stable).
  void bin(const double* x, const double* y, std::size_t n);

  /// x wrapped into [lo, hi) along a periodic direction; unchanged otherwise.
  double wrap_x(double x) const;
  double wrap_y(double y) const;

  /// f(j, sx, sy) for each binned particle j in the (wrapped) 3 x 3 block around (px, py): the
  /// image of j near the point is at (x_j + sx, y_j + sy).
  template <class F> void for_each_near(double px, double py, F&& f) const {
    const int cx = cell_x(px), cy = cell_y(py);
    for (int dy = -1; dy <= 1; ++dy) {
      int ry = cy + dy;
      double sy = 0.0;
      if (!wrap_cell(ry, sy, ny_, period_.y(), periodic_y_)) continue;
      for (int dx = -1; dx <= 1; ++dx) {
        int rx = cx + dx;
        double sx = 0.0;
        if (!wrap_cell(rx, sx, nx_, period_.x(), periodic_x_)) continue;
        const std::size_t c = static_cast<std::size_t>(ry * nx_ + rx);
        for (std::uint32_t k = start_[c]; k < start_[c + 1]; ++k) f(order_[k], sx, sy);
      }
    }
  }

  int cell_x(double x) const;
  int cell_y(double y) const;
  int nx() const { return nx_; }
  int ny() const { return ny_; }
  const std::vector<std::uint32_t>& order() const { return order_; }

private:
  /// Cell index r along an axis of n cells: wrapped into [0, n) with the image shift s (-L, 0 or
  /// L) if the axis is periodic; false if r is off a non-periodic axis.
  static bool wrap_cell(int& r, double& s, int n, double L, bool periodic) {
    if (!periodic) return r >= 0 && r < n;
    if (r < 0) r += n, s = -L;
    if (r >= n) r -= n, s = L;
    return true;
  }

  Vec2 lo_ = Vec2::Zero(), period_ = Vec2::Zero(), inv_cell_ = Vec2::Zero();
  int nx_ = 1, ny_ = 1;
  bool periodic_x_ = false, periodic_y_ = false;
  std::vector<std::uint32_t> cell_, start_, order_;
};

} // namespace fsi::particles
