#pragma once
// Verlet neighbour list in D = 2 or 3 dimensions: for each particle, the others within r_e
// (1 + skin) when it was built. It stays valid while no particle has moved more than skin r_e / 2
// since, so one build serves many steps; rows have a fixed capacity (no allocation per build).
#include "particles/cell_grid.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace fsi::particles {

template <int D> class BasicNeighborList {
public:
  /// Rebuilds for n particles binned in `grid` at positions x. Returns false if some row
  /// overflowed its capacity (the particle index is then in overflow()). `vector`: test eight
  /// candidates at once with AVX-512 where the CPU has it (avx512_available()); the rows are the
  /// same, in the same order.
  bool build(const BasicCellGrid<D>& grid, const Coords<D>& x, std::size_t n, double radius,
             std::size_t capacity, bool vector = true);
  bool build(const BasicCellGrid<D>& grid, const double* x, const double* y, std::size_t n,
             double radius, std::size_t capacity, bool vector = true) requires(D == 2) {
    return build(grid, Coords<D>{x, y}, n, radius, capacity, vector);
  }

  /// True while every particle is within `half_skin` of where it was at the last build.
  bool valid(const Coords<D>& x, std::size_t n, double half_skin) const;
  bool valid(const double* x, const double* y, std::size_t n, double half_skin) const
      requires(D == 2) {
    return valid(Coords<D>{x, y}, n, half_skin);
  }

  const std::uint32_t* row(std::size_t i) const { return &index_[i * capacity_]; }
  std::uint32_t count(std::size_t i) const { return count_[i]; }
  std::size_t overflow() const { return overflow_; }
  double mean_count() const;
  void invalidate() { built_n_ = 0; }
  /// Particles of the last valid build (0 after invalidate()) and their positions then, per axis:
  /// a checkpoint stores these, and build() from them gives the same list again.
  std::size_t built() const { return built_n_; }
  const std::vector<double>& build_positions(int axis) const {
    return build_[static_cast<std::size_t>(axis)];
  }
  const std::vector<double>& x_build() const { return build_[0]; }
  const std::vector<double>& y_build() const { return build_[1]; }

private:
  std::size_t capacity_ = 0, built_n_ = 0, overflow_ = 0;
  std::vector<std::uint32_t> index_, count_;
  std::array<std::vector<double>, D> build_;
};

extern template class BasicNeighborList<2>;
extern template class BasicNeighborList<3>;

/// The 2-D list of the 2-D solvers.
using NeighborList = BasicNeighborList<2>;

} // namespace fsi::particles
