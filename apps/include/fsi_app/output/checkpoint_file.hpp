#pragma once
// Checkpoint files: a StateArchive as HDF5, one dataset per key (key "fluid/x" is the dataset
// /fluid/x; reals float64, integers int64). Written to FILE.tmp, flushed, closed and renamed,
// so a checkpoint on disk is always whole (a crash leaves the old one or the new one).
#include "fsi/core/state_archive.hpp"

#include <filesystem>

namespace fsi::app {

/// Throws RunError when the file cannot be written.
void write_checkpoint(const std::filesystem::path& file, const StateArchive& archive);

/// Throws InputError (`FILE: what`) when the file cannot be opened or read.
StateArchive read_checkpoint(const std::filesystem::path& file);

} // namespace fsi::app
