#pragma once
// Progress of a run: a live line on a terminal, a plain log line at most every few seconds
// otherwise.
#include <chrono>
#include <ostream>

namespace fsi::app {

class Progress {
public:
  Progress(double end_time, bool terminal, std::ostream& out);
  void update(double time, long steps);
  void finish(double time, long steps);

private:
  std::string line(double time, long steps) const;
  double end_;
  bool terminal_;
  std::ostream& out_;
  std::chrono::steady_clock::time_point start_, last_;
};

} // namespace fsi::app
