#pragma once
// Line-oriented output files (probes.csv, coupling.csv) continued after a restart.
#include <cstddef>
#include <filesystem>

namespace fsi::app {

/// Keeps the first `lines` lines of a text file and drops the rest (rewritten to a temporary
/// name, then renamed). Throws InputError when the file is missing or shorter.
void keep_lines(const std::filesystem::path& file, std::size_t lines);

} // namespace fsi::app
