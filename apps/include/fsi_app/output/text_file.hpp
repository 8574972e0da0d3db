#pragma once
// Line-oriented output files (probes.csv, coupling.csv) continued after a restart, and small
// files written whole (run.json, checkpoints) that are never seen half-written.
#include <cstddef>
#include <filesystem>
#include <string>

namespace fsi::app {

/// Keeps the first `lines` lines of a text file and drops the rest (rewritten to a temporary
/// name, then renamed). Throws InputError when the file is missing or shorter.
void keep_lines(const std::filesystem::path& file, std::size_t lines);

/// Writes `size` bytes to FILE.tmp, flushes them to disk (fsync, unless `sync` is false: an index
/// rewritten often, like fields.xmf), closes and renames it to FILE:
/// FILE is the old file or the new one, never a part. On any failure (a full disk: ENOSPC, or
/// EFBIG past RLIMIT_FSIZE) FILE.tmp is removed and RunError `PREFIX FILE: what` is thrown; a
/// full disk (ENOSPC, EDQUOT) says `(disk full; NAME is left as it was before this write)`, the
/// size limit (EFBIG) likewise.
void write_file_atomically(const std::filesystem::path& file, const void* data, std::size_t size,
                           const std::string& prefix = "output: ", bool sync = true);
inline void write_file_atomically(const std::filesystem::path& file, const std::string& text,
                                  const std::string& prefix = "output: ", bool sync = true) {
  write_file_atomically(file, text.data(), text.size(), prefix, sync);
}

} // namespace fsi::app
