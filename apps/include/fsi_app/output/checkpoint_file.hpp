#pragma once
// Checkpoint files: a StateArchive as HDF5, one dataset per key (key "fluid/x" is the dataset
// /fluid/x; reals float64, integers int64). Written to FILE.tmp, flushed, closed and renamed,
// so a checkpoint on disk is always whole (a crash leaves the old one or the new one). Each
// dataset carries its checksum (attribute `fnv1a64`, FNV-1a over the 8 little-endian bytes of
// every value); a dataset whose values do not match it, or a NaN, is refused on reading.
#include "fsi/core/state_archive.hpp"

#include <cstdint>
#include <filesystem>
#include <vector>

namespace fsi::app {

/// FNV-1a (64 bit) over the values' little-endian bytes: the checksum stored per dataset.
std::uint64_t checkpoint_checksum(const std::vector<double>& values);
std::uint64_t checkpoint_checksum(const std::vector<std::int64_t>& values);

/// Throws RunError when the file cannot be written (FILE.tmp is then removed, FILE untouched).
void write_checkpoint(const std::filesystem::path& file, const StateArchive& archive);

/// Throws InputError (`FILE: what`) when the file cannot be opened or read, when a dataset does
/// not match its checksum or holds a NaN (both naming the dataset; a NaN is accepted in the
/// wall-hit cache `*/hits/*` and in the state of a failed step, `driver/failed` = 1, which the
/// driver refuses itself).
StateArchive read_checkpoint(const std::filesystem::path& file);

} // namespace fsi::app
