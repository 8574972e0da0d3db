#pragma once
// Verlet neighbour list: for each particle, the others within r_e (1 + skin) when it was built.
// It stays valid while no particle has moved more than skin r_e / 2 since, so one build serves
// many steps; rows have a fixed capacity (no allocation per build).
#include "particles/cell_grid.hpp"

#include <cstdint>
#include <vector>

namespace fsi::particles {

class NeighborList {
public:
  /// Rebuilds for n particles binned in `grid` at positions (x, y). Returns false if some row
  /// overflowed its capacity (the particle index is then in overflow()). `vector`: test eight
  /// candidates at once with AVX-512 where the CPU has it (avx512_available()); the rows are the
  /// same, in the same order.
  bool build(const CellGrid& grid, const double* x, const double* y, std::size_t n, double radius,
             std::size_t capacity, bool vector = true);

  /// True while every particle is within `half_skin` of where it was at the last build.
  bool valid(const double* x, const double* y, std::size_t n, double half_skin) const;

  const std::uint32_t* row(std::size_t i) const { return &index_[i * capacity_]; }
  std::uint32_t count(std::size_t i) const { return count_[i]; }
  std::size_t overflow() const { return overflow_; }
  double mean_count() const;
  void invalidate() { built_n_ = 0; }
  /// Particles of the last valid build (0 after invalidate()) and their positions then: a
  /// checkpoint stores these, and build() from them gives the same list again.
  std::size_t built() const { return built_n_; }
  const std::vector<double>& x_build() const { return x_build_; }
  const std::vector<double>& y_build() const { return y_build_; }

private:
  std::size_t capacity_ = 0, built_n_ = 0, overflow_ = 0;
  std::vector<std::uint32_t> index_, count_;
  std::vector<double> x_build_, y_build_;
};

} // namespace fsi::particles
