#pragma once
// Bitwise equality of two fluids' particle states (restart and thread tests).
#include "fluid_sph/sph_fluid.hpp"

namespace fsi::sph {

inline bool same_state(const SphFluid& a, const SphFluid& b) {
  const auto& p = a.particles();
  const auto& q = b.particles();
  if (p.size() != q.size() || a.time() != b.time() || a.steps() != b.steps()) return false;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.x[0][i] != q.x[0][i] || p.x[1][i] != q.x[1][i] || p.v[0][i] != q.v[0][i] ||
        p.v[1][i] != q.v[1][i] || p.rho[i] != q.rho[i] || p.id[i] != q.id[i])
      return false;
  return true;
}

} // namespace fsi::sph
