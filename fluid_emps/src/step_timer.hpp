#pragma once
// Adds the wall time of a scope to one of the step's StepTimes counters, less the seconds this
// process waited in collectives meanwhile (particles::Decomposition::waited_seconds), which go
// to StepTimes::waited: each part is this process's own work, the waits its share of the load
// imbalance (docs/performance.md "Scaling under mpirun").
#include "fluid_emps/emps_fluid.hpp"
#include "fsi/core/parallel.hpp"

namespace fsi::emps {

template <int D> class Timer {
public:
  Timer(double& sink, StepTimes& times, const particles::Decomposition<D>& hook)
      : sink_(sink), waited_(times.waited), hook_(hook), start_(wall_time()),
        waited_start_(hook.waited_seconds()) {}
  ~Timer() {
    const double waited = hook_.waited_seconds() - waited_start_;
    sink_ += wall_time() - start_ - waited;
    waited_ += waited;
  }
  Timer(const Timer&) = delete;
  Timer& operator=(const Timer&) = delete;

private:
  double &sink_, &waited_;
  const particles::Decomposition<D>& hook_;
  double start_, waited_start_;
};

} // namespace fsi::emps
