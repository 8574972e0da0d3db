#pragma once
// The momentum test of the pair terms in 2-D and 3-D: random velocities, then the largest change
// of the total momentum over one acoustic step.
#include "fluid_sph/sph_fluid.hpp"

#include <algorithm>
#include <random>
#include <vector>

namespace fsi::sph {

/// Sets velocities with components uniform in [-1, 1] (seed 11), runs `steps` acoustic steps and
/// returns the largest |P(t + dt) - P(t)| / sum_i m |v_i(0)|.
template <int D> double worst_momentum_change(BasicSphFluid<D>& f, int steps) {
  std::mt19937 gen(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<VecD<D>> v(f.particles().size());
  for (auto& w : v)
    for (int c = 0; c < D; ++c) w[c] = u(gen);
  f.set_velocities(v);
  double scale = 0.0;
  for (const auto& w : v) scale += f.options().mass() * w.norm();
  VecD<D> m = f.momentum();
  double worst = 0.0;
  for (int s = 0; s < steps; ++s) {
    f.advance(f.next_dt());
    const VecD<D> m1 = f.momentum();
    worst = std::max(worst, (m1 - m).norm() / scale);
    m = m1;
  }
  return worst;
}

} // namespace fsi::sph
