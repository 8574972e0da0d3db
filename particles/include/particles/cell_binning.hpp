#pragma once
// What BasicCellGrid and BasicPeriodicGrid share: D axes of cells (axis a: n[a] cells of side
// 1 / inv_side[a] from lo[a]), numbered x fastest, then y, then z, and the particles binned into
// them by a stable counting sort (cost linear in N; within a cell, particles keep their index
// order, so the binning is deterministic).
#include "fsi/core/types.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace fsi::particles {

/// D coordinate arrays indexed by particle: x, y (and z).
template <int D> using Coords = std::array<const double*, D>;

template <int D> class CellBinning {
  static_assert(D == 2 || D == 3, "the grids are instantiated for D = 2 and D = 3");

public:
  /// Bins n particles; afterwards cell c holds order()[start(c) .. start(c + 1)).
  void bin(const Coords<D>& x, std::size_t n);
  void bin(const double* x, const double* y, std::size_t n) requires(D == 2) {
    bin(Coords<D>{x, y}, n);
  }

  /// The cell of coordinate v along `axis`, clamped to the edge cells.
  int cell(int axis, double v) const;
  int cell_x(double x) const { return cell(0, x); }
  int cell_y(double y) const { return cell(1, y); }
  int cells(int axis) const { return n_[static_cast<std::size_t>(axis)]; }
  int nx() const { return n_[0]; }
  int ny() const { return n_[1]; }
  const std::vector<std::uint32_t>& order() const { return order_; }

protected:
  CellBinning() { n_.fill(1); }
  /// Sets the axes and sizes the cell table (prod n + 1 starts).
  void set_axes(const VecD<D>& lo, const VecD<D>& inv_side, const std::array<int, D>& n);

  VecD<D> lo_ = VecD<D>::Zero(), inv_side_ = VecD<D>::Zero();
  std::array<int, D> n_;
  std::vector<std::uint32_t> cell_;  // per particle
  std::vector<std::uint32_t> start_; // per cell, prod(n) + 1 (start_[c + 1] ends cell c)
  std::vector<std::uint32_t> order_;
};

extern template class CellBinning<2>;
extern template class CellBinning<3>;

} // namespace fsi::particles
