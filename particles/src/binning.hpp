#pragma once
// Binning of CellBinning: the cell index along an axis, and the counting sort (cost linear in the
// particle count; stable: within a cell, particles keep their index order, so the binning is
// deterministic).
#include "fsi/core/parallel.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace fsi::particles::detail {

/// The cell of coordinate v along an axis of n cells of side 1 / inv_side from lo, clamped to the
/// edge cells.
inline int cell_index(double v, double lo, double inv_side, int n) {
  const double c = std::floor((v - lo) * inv_side);
  return static_cast<int>(std::clamp(c, 0.0, static_cast<double>(n - 1)));
}

/// Bins n particles by cell_of(i) in [0, start.size() - 1): afterwards cell c holds
/// order[start[c] .. start[c + 1]) and slot[i] is the position of particle i in order.
template <class CellOf>
void sort_by_cell(std::size_t n, CellOf&& cell_of, std::vector<std::uint32_t>& slot,
                  std::vector<std::uint32_t>& start, std::vector<std::uint32_t>& order) {
  slot.resize(n);
  order.resize(n);
  parallel_for(n, [&](std::size_t i) { slot[i] = cell_of(i); });
  std::fill(start.begin(), start.end(), 0u);
  for (std::size_t i = 0; i < n; ++i) ++start[slot[i] + 1];
  for (std::size_t c = 1; c < start.size(); ++c) start[c] += start[c - 1];
  for (std::size_t i = 0; i < n; ++i) slot[i] = start[slot[i]]++; // cell -> position in order
  for (std::size_t i = 0; i < n; ++i) order[slot[i]] = static_cast<std::uint32_t>(i);
  // start was advanced to the ends of the cells: shift back by one cell.
  for (std::size_t c = start.size() - 1; c > 0; --c) start[c] = start[c - 1];
  start[0] = 0;
}

} // namespace fsi::particles::detail
