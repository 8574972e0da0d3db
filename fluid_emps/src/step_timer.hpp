#pragma once
// Adds the wall time of a scope to one of the step's StepTimes counters.
#include "fsi/core/parallel.hpp"

namespace fsi::emps {

class Timer {
public:
  explicit Timer(double& sink) : sink_(sink), start_(wall_time()) {}
  ~Timer() { sink_ += wall_time() - start_; }
  Timer(const Timer&) = delete;
  Timer& operator=(const Timer&) = delete;

private:
  double& sink_;
  double start_;
};

} // namespace fsi::emps
