#pragma once
// The particles a process holds when a decomposed fluid is built (issue 47): not the whole fill
// but its block of ids [first, last), first = floor(n rank / P). The ids are the fill's indices,
// as on one process, so output in id order and the answer are those of one process; a block is
// contiguous in the fill's order (lattices filled row by row, region by region), so compact in
// space: the first partition moves fewer particles than a scattered share (i mod P) would, and
// no process holds more than ceil(n / P). The fluid's start (pair sums, initial pressures) waits
// for decompose(), which partitions the blocks over the processes first.
#include "particles/field_set.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace fsi::particles {

/// How a fluid is built: the whole fill, started at once (one process, the default), or one
/// process's block of it, ids from `first`, started by decompose() (`deferred`).
struct SetupBlock {
  std::size_t first = 0; ///< the id of the first position given
  bool deferred = false;
};

/// Ids [first, last) of process `rank`'s block of a fill of n over `processes`.
struct BlockRange {
  std::size_t first = 0, last = 0;
  std::size_t size() const { return last - first; }
};
inline BlockRange block_of(std::size_t n, int rank, int processes) {
  const auto r = static_cast<std::size_t>(rank), p = static_cast<std::size_t>(processes);
  return {n * r / p, n * (r + 1) / p};
}

/// Every process holding the same whole set (a fluid built whole, a checkpoint each process
/// read): keeps this process's block of its entries (in their order), drops the others.
inline void keep_block(FieldSet& fields, int rank, int processes, std::vector<std::uint8_t>& keep) {
  const BlockRange b = block_of(fields.size(), rank, processes);
  keep.assign(fields.size(), 0);
  for (std::size_t i = b.first; i < b.last; ++i) keep[i] = 1;
  fields.compact(keep);
}

} // namespace fsi::particles
