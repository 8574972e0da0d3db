#pragma once
// Axis-aligned boxes (a triangle's bounding box, say) binned into a uniform grid of cubic cells:
// every cell a box overlaps lists it, in box order (CSR arrays, a counting sort). A point of a box
// lies in a cell that lists it, so the boxes listed by the cells overlapping a query cube
// [q - r, q + r] include every triangle within r of q. The one copy for geometry_erp's
// TriangleLocator and fluid_sph's InterfaceBoundary3.
#include "fsi/core/types.hpp"

#include <array>
#include <span>
#include <vector>

namespace fsi::particles {

/// A box [lo, hi].
struct Box3d {
  Vec3 lo, hi;
};

class BoxGrid {
public:
  /// Bins `boxes` into cells of side h >= min_cell (h grown by 1.25 until there are at most 2^22
  /// cells: a wide domain gets larger cells rather than a huge grid) over the finite boxes'
  /// bounding box; a box with a non-finite corner is binned nowhere. Capacity is kept between
  /// builds.
  void build(std::span<const Box3d> boxes, double min_cell);

  double cell_size() const { return h_; }
  /// The grid's lower corner (the finite boxes' lowest, 0 when there is none).
  const Vec3& origin() const { return lo_; }
  /// Cells along x, y, z.
  const std::array<int, 3>& dims() const { return n_; }
  /// Index of cell (i, j, k), x fastest.
  std::size_t cell(int i, int j, int k) const {
    return (static_cast<std::size_t>(k) * static_cast<std::size_t>(n_[1]) +
            static_cast<std::size_t>(j)) *
               static_cast<std::size_t>(n_[0]) +
           static_cast<std::size_t>(i);
  }
  /// Cell c lists entries()[begin(c) .. begin(c + 1)).
  int begin(std::size_t c) const { return begin_[c]; }
  /// The boxes' indices, cell after cell.
  const std::vector<int>& entries() const { return entry_; }
  /// The boxes listed by the cells overlapping [lo, hi], ascending without repeats, into out.
  void overlapping(const Vec3& lo, const Vec3& hi, std::vector<int>& out) const;

private:
  double h_ = 0.0;
  Vec3 lo_ = Vec3::Zero();
  std::array<int, 3> n_{0, 0, 0};
  std::vector<int> begin_; // CSR offsets into entry_
  std::vector<int> entry_;
};

} // namespace fsi::particles
