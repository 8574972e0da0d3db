#pragma once
// The run's output folder: one run per folder (a lock), the files a run writes there, and its
// checkpoints' names and pruning (docs/reliability.md).
#include <filesystem>
#include <string>

namespace fsi::app {

/// The files a run writes in its output folder (and their temporary names).
bool is_run_file(const std::string& name);

/// DIR/checkpoint_<step, 9 digits>.h5.
std::filesystem::path checkpoint_path(const std::filesystem::path& out, long step);

/// Deletes all but the newest `keep` checkpoint_*.h5 up to `step` (later ones belong to a run
/// that a restart abandoned; they are overwritten as this one gets there).
void prune_checkpoints(const std::filesystem::path& out, long step, int keep);

/// One run per output folder: flock on DIR/.lock, held until the process ends or the run
/// returns. Taken before anything else is written; a folder of another run is refused unless
/// `overwrite` (then exactly the run files are deleted).
class OutputLock {
public:
  /// Throws InputError (`DIR: --out: what`).
  OutputLock(const std::filesystem::path& out, bool fresh, bool overwrite);
  ~OutputLock();
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;

private:
  int fd_ = -1;
};

} // namespace fsi::app
