#pragma once
// Cell-linked list: particles binned into square cells of side h by a counting sort (cost linear
// in N); the cells of a row are contiguous in `order`, so the 3 x 3 block around a point is three
// contiguous ranges. With h >= the search radius, the block holds every particle within h.
#include "fsi/core/types.hpp"

#include <cstdint>
#include <vector>

namespace fsi::particles {

class CellGrid {
public:
  /// Covers [lo, hi] with one spare cell on every side.
  CellGrid(const Vec2& lo, const Vec2& hi, double h);

  /// Bins n particles; afterwards cell c holds order()[begin(c) .. begin(c+1)).
  void bin(const double* x, const double* y, std::size_t n);

  int cell_x(double x) const;
  int cell_y(double y) const;
  int nx() const { return nx_; }
  int ny() const { return ny_; }
  double h() const { return h_; }
  const std::vector<std::uint32_t>& order() const { return order_; }
  std::uint32_t begin(int cx, int cy) const {
    return start_[static_cast<std::size_t>(cy * nx_ + cx)];
  }

  /// The 3 x 3 cell block around a point, clamped to the grid: cells x0..x1 of rows y0..y1. Row
  /// r's particles are order()[begin(x0, r) .. begin(x1 + 1, r)).
  struct Block {
    int x0, x1, y0, y1;
  };
  Block block_near(double px, double py) const {
    const int cx = cell_x(px), cy = cell_y(py);
    return {cx > 0 ? cx - 1 : 0, cx + 1 < nx_ ? cx + 1 : nx_ - 1, cy > 0 ? cy - 1 : 0,
            cy + 1 < ny_ ? cy + 1 : ny_ - 1};
  }
  /// f(j) for every binned particle j in the 3 x 3 cell block around (px, py), clamped to the grid.
  template <class F> void for_each_near(double px, double py, F&& f) const {
    const Block b = block_near(px, py);
    for (int r = b.y0; r <= b.y1; ++r)
      for (std::uint32_t k = begin(b.x0, r), end = begin(b.x1 + 1, r); k < end; ++k) f(order_[k]);
  }

private:
  Vec2 lo_;
  double h_, inv_h_;
  int nx_, ny_;
  std::vector<std::uint32_t> cell_;  // per particle
  std::vector<std::uint32_t> start_; // per cell, nx*ny + 1 (begin(nx, r) is the next row's start)
  std::vector<std::uint32_t> order_;
};

} // namespace fsi::particles
