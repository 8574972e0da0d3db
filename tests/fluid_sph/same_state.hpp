#pragma once
// Bitwise equality of two fluids' particle states (restart and thread tests).
#include "fluid_sph/sph_fluid.hpp"

namespace fsi::sph {

inline bool same_state(const SphFluid& a, const SphFluid& b) {
  const auto& p = a.particles();
  const auto& q = b.particles();
  if (p.size() != q.size() || a.time() != b.time() || a.steps() != b.steps()) return false;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.x[i] != q.x[i] || p.y[i] != q.y[i] || p.vx[i] != q.vx[i] || p.vy[i] != q.vy[i] ||
        p.rho[i] != q.rho[i] || p.id[i] != q.id[i])
      return false;
  return true;
}

} // namespace fsi::sph
