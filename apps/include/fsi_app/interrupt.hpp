#pragma once
// SIGINT / SIGTERM during a run: the handler only records the signal; the driver finishes the
// step in progress, writes a checkpoint, closes its output and returns (exit status 128 + signal:
// 130 for SIGINT, 143 for SIGTERM). A second signal ends the process at once with the same
// status, after writing the run.json the driver left with set_last_words ("interrupted").
#include <filesystem>
#include <string>

namespace fsi::app {

class InterruptGuard {
public:
  /// Installs the handlers; the destructor restores the previous ones. Re-entrant: while guards
  /// nest or overlap (any order, any thread) the first installs and the last restores, and a
  /// signal stops every run they guard.
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  /// The signal received since the first live guard was made, or 0.
  int received() const;
  /// What a second signal writes (to FILE.tmp, renamed to FILE) before it ends the process.
  void set_last_words(const std::filesystem::path& file, const std::string& text);
};

} // namespace fsi::app
