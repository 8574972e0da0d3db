#pragma once
// Cell-linked list in D = 2 or 3 dimensions: particles binned into cubic cells of side h by a
// counting sort (cost linear in N). Cells are numbered x fastest, then y, then z, so the cells of a
// row (fixed y and z) are contiguous in `order` and the 3^D block around a point is 3^(D-1)
// contiguous ranges. With h >= the search radius, the block holds every particle within h.
#include "particles/cell_binning.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace fsi::particles {

template <int D> class BasicCellGrid : public CellBinning<D> {
public:
  /// Covers [lo, hi] with one spare cell on every side.
  BasicCellGrid(const VecD<D>& lo, const VecD<D>& hi, double h);

  using CellBinning<D>::cell;
  using CellBinning<D>::cells;
  double h() const { return h_; }
  /// First slot of cell cx of row `row` (row = cy in 2-D, cz ny + cy in 3-D); begin(nx, row) is
  /// the next row's start.
  std::uint32_t begin(int cx, int row) const {
    return start_[static_cast<std::size_t>(row * n_[0] + cx)];
  }

  /// Rows of the 3^D block around a point (at most 3^(D-1)).
  static constexpr int max_rows = D == 2 ? 3 : 9;
  /// The 3^D cell block around a point, clamped to the grid: cells x0..x1 of rows row[0 .. rows),
  /// y fastest. Row k's particles are order()[begin(x0, row[k]) .. begin(x1 + 1, row[k])).
  struct Block {
    int x0, x1, rows;
    std::array<int, max_rows> row;
  };
  Block block_near(const VecD<D>& p) const {
    Block b{};
    near(0, p[0], b.x0, b.x1);
    int y0, y1;
    near(1, p[1], y0, y1);
    if constexpr (D == 2) {
      for (int y = y0; y <= y1; ++y) b.row[static_cast<std::size_t>(b.rows++)] = y;
    } else {
      int z0, z1;
      near(2, p[2], z0, z1);
      for (int z = z0; z <= z1; ++z)
        for (int y = y0; y <= y1; ++y) b.row[static_cast<std::size_t>(b.rows++)] = z * n_[1] + y;
    }
    return b;
  }
  Block block_near(double px, double py) const requires(D == 2) {
    return block_near(plane_point(px, py));
  }

  /// f(j) for every binned particle j in the 3^D cell block around p, clamped to the grid.
  template <class F> void for_each_near(const VecD<D>& p, F&& f) const {
    const Block b = block_near(p);
    for (int r = 0; r < b.rows; ++r) {
      const int row = b.row[static_cast<std::size_t>(r)];
      for (std::uint32_t k = begin(b.x0, row), end = begin(b.x1 + 1, row); k < end; ++k)
        f(order_[k]);
    }
  }
  template <class F> void for_each_near(double px, double py, F&& f) const requires(D == 2) {
    for_each_near(plane_point(px, py), f);
  }

private:
  /// (px, py) as a VecD<D>: well-formed for every D, since an explicit instantiation for D = 3
  /// may instantiate the 2-D forms' bodies (clang 14) although their constraint excludes them.
  static VecD<D> plane_point(double px, double py) {
    VecD<D> p = VecD<D>::Zero();
    p[0] = px;
    p[1] = py;
    return p;
  }
  using CellBinning<D>::n_;
  using CellBinning<D>::start_;
  using CellBinning<D>::order_;

  /// The cells c0..c1 around coordinate v along `axis`: its cell and the two beside, clamped.
  void near(int axis, double v, int& c0, int& c1) const {
    const int c = cell(axis, v), n = cells(axis);
    c0 = c > 0 ? c - 1 : 0;
    c1 = c + 1 < n ? c + 1 : n - 1;
  }

  double h_;
};

extern template class BasicCellGrid<2>;
extern template class BasicCellGrid<3>;

/// The 2-D grid of the 2-D solvers.
using CellGrid = BasicCellGrid<2>;

} // namespace fsi::particles
