#pragma once
// The run driver's guard over a particle fluid's count (issue 41): particles that leave the
// domain are removed and counted, so a fluid that empties, or loses more than kMaxStepLoss of its
// particles in one step, would otherwise end "completed"; it stops the run instead.
#include "fsi/core/types.hpp"

#include <Eigen/Core>

#include <cstddef>
#include <utility>

namespace fsi::app {

/// A particle fluid's count and the box outside which its particles are removed.
struct ParticleCount {
  std::size_t count = 0;
  std::pair<Eigen::VectorXd, Eigen::VectorXd> domain; ///< lower and upper corner, D components
};

/// The largest fraction of a step's particles that may leave in that step.
inline constexpr double kMaxStepLoss = 0.25;

/// Throws RunError (how many of how many, the domain, the step and its times) when `after` is 0
/// or fewer than (1 - kMaxStepLoss) of `before`.
void check_particle_loss(const ParticleCount& before, const ParticleCount& after, long step,
                         double t_start, double t_end);

} // namespace fsi::app
