#pragma once
// The thread count of a run's next steps, chosen by their measured wall time (issue 48, item 3).
// A core shared with another process makes n OpenMP threads slower than fewer, up to ten times
// with spinning barriers (docs/performance.md, "Threads beside a competing process"). The state
// of a run does not depend on the thread count (docs/reliability.md, "Determinism"), so a switch
// changes the speed only. `--threads N` is the most the governor uses.
#include "fsi_app/output/json.hpp"

#include <vector>

namespace fsi::app {

class ThreadGovernor {
public:
  /// Steps timed in each window; the median of a window is its figure (a list rebuild inside a
  /// window does not decide).
  static constexpr int kWindow = 9;
  /// A trial's count replaces the current one when its median step is this much faster.
  static constexpr double kMargin = 0.10;
  /// A trial ends at once, lost, on a step this many times the current count's median: a count
  /// whose barriers spin on a shared core costs up to ten steps a step, so a trial costs one.
  static constexpr double kAbort = 2.0;
  /// The first trial follows the first window; then kFirstPeriod steps at the current count
  /// before the next trial, doubled after each lost one up to kLongestPeriod (so trials cost
  /// well under 1 % of a steady run), kFirstPeriod again after a switch.
  static constexpr long kFirstPeriod = 30, kLongestPeriod = 7680;

  explicit ThreadGovernor(int most);
  /// The thread count for the next step.
  int threads() const { return trial_ ? trial_threads_ : current_; }
  /// The wall seconds of the step just taken at threads().
  void record(double seconds);

  int most() const { return most_; }
  long switches() const { return switches_; }
  long trials() const { return trials_; }
  /// Steps taken at each count: steps_at()[n - 1] for n threads.
  const std::vector<long>& steps_at() const { return steps_at_; }
  /// run.json's `thread_governor`: switches, trials and steps_at.
  JsonObject report() const;

private:
  void start_trial();
  void end_trial();

  int most_, current_, trial_threads_ = 0;
  bool trial_ = false, trial_upward_ = false;
  long period_ = kWindow, since_trial_ = 0, switches_ = 0, trials_ = 0;
  std::vector<double> reference_, window_; // the last kWindow steps at current_; the trial's
  std::vector<long> steps_at_;
};

} // namespace fsi::app
