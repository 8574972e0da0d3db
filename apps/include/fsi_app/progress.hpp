#pragma once
// Progress of a run: a live line on a terminal, a plain log line at most every few seconds
// otherwise.
#include <chrono>
#include <ostream>
#include <string>

namespace fsi::app {

class Progress {
public:
  /// A restarted run counts its rate and ETA from (first_step, first_time).
  Progress(double end_time, bool terminal, std::ostream& out, long first_step = 0,
           double first_time = 0.0);
  void update(double time, long steps);
  void finish(double time, long steps);
  /// The progress text: `t = T s  P %  R steps/s  ETA MmSSs`, P within [0, 100].
  std::string line(double time, long steps) const;

private:
  double end_;
  long first_step_;
  double first_time_;
  bool terminal_;
  std::ostream& out_;
  std::chrono::steady_clock::time_point start_, last_;
};

} // namespace fsi::app
