#pragma once
// SIGINT / SIGTERM during a run: the handler only records the signal; the driver finishes the
// step in progress, writes a checkpoint, closes its output and returns (exit status 128 + signal:
// 130 for SIGINT, 143 for SIGTERM). A second signal gets the default action (immediate end).
namespace fsi::app {

class InterruptGuard {
public:
  /// Installs the handlers; the destructor restores the previous ones.
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  /// The signal received since construction, or 0.
  int received() const;
};

} // namespace fsi::app
