#include "coupling/stats.hpp"

#include <algorithm>

namespace fsi::coupling {

void CouplingSummary::add(const StepStats& s) {
  ++steps;
  iterations += s.iterations;
  max_iterations = std::max(max_iterations, s.iterations);
  if (!s.converged) ++unconverged;
  time_fluid += s.time_fluid;
  time_structure += s.time_structure;
  time_coupler += s.time_coupler;
}

} // namespace fsi::coupling
