#include "fsi_app/particle_guard.hpp"

#include "fsi/core/error.hpp"

#include <sstream>
#include <string>

namespace fsi::app {

namespace {

std::string point(const Eigen::VectorXd& x) {
  std::ostringstream s;
  for (Eigen::Index c = 0; c < x.size(); ++c) s << (c ? ", " : "(") << x[c];
  return s.str() + ")";
}

} // namespace

void check_particle_loss(const ParticleCount& before, const ParticleCount& after, long step,
                         double t_start, double t_end) {
  const bool empty = after.count == 0;
  if (!empty &&
      static_cast<double>(after.count) >= (1.0 - kMaxStepLoss) * static_cast<double>(before.count))
    return;
  const auto& [lo, hi] = after.domain;
  std::ostringstream s;
  s << "fluid: " << before.count - after.count << " of " << before.count
    << " particles left the domain [" << point(lo) << ", " << point(hi) << "] m in step " << step
    << ", t = " << t_start << " -> " << t_end << " s: "
    << (empty ? "the fluid is empty"
              : "more than " + std::to_string(static_cast<int>(100 * kMaxStepLoss)) +
                    " % in one step")
    << " (check gravity, time.courant and fluid.domain)";
  throw RunError(s.str());
}

} // namespace fsi::app
