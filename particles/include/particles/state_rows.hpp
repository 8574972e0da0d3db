#pragma once
// Per-particle arrays of a checkpoint, by row (issue 47): a decomposed particle solver writes
// one checkpoint in the one-process format (every process's owned particles gathered to process
// 0 in id order) and a restart on any process count hands each process the rows of the
// particles it owns after partitioning the checkpoint afresh. `rows` archives hold per-particle
// arrays only, each a whole number of values a particle (a VecD flattened: D values), all for
// the same particles.
#include "fsi/core/state_archive.hpp"
#include "particles/decomposition.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace fsi::particles {

/// Rows `pick` (in that order) of every array of `rows` (`n` particles) into `out`.
void select_rows(const StateArchive& rows, std::size_t n, const std::vector<std::size_t>& pick,
                 StateArchive& out);

/// Collective: every process's `rows` into `out` on process 0, ordered by the particles' ids
/// (the integer array `id_key` of `rows`); nothing on the others. Every process's archive has
/// the same keys.
template <int D>
void gather_rows(const Decomposition<D>& decomposition, const StateArchive& rows,
                 const std::string& id_key, StateArchive& out);

} // namespace fsi::particles
