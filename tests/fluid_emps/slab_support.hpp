#pragma once
// What the quasi-2-D slab tests share (test_emps3d_slab.cpp, test_emps3d_periodic.cpp): the
// shipped dam break's water at l0 = 0.01 m (the standard wall preset, slip walls, gravity -y),
// its 2-D twin, the 2-D lattice ordered as the 3-D block's layers, and a lattice column's range
// across z.
#include "test_support.hpp"

#include <algorithm>
#include <utility>
#include <vector>

namespace fsi::emps::test {

inline constexpr double l0 = 0.01;
inline constexpr int nz = 6; // the slab's depth in l0

/// The shipped dam break's wall (the standard preset) with slip walls, gravity -y.
inline FluidOptions3 slab_water() {
  FluidOptions3 o = water<3>(l0, -0.1, 0.3);
  apply_wall_preset(o, WallModel::standard);
  o.viscosity = 1e-6;
  o.wall.contact.alpha_rep = 1e5;
  o.wall.mirror.condition = WallCondition::slip;
  o.gravity = Vec3(0, -9.81, 0);
  return o;
}

/// The 2-D twin: the same keys, x-y plane.
inline FluidOptions plane_water() {
  const FluidOptions3 s = slab_water();
  FluidOptions o = water<2>(l0, -0.1, 0.3);
  apply_wall_preset(o, WallModel::standard);
  o.viscosity = s.viscosity;
  o.wall.contact.alpha_rep = s.wall.contact.alpha_rep;
  o.wall.mirror.condition = s.wall.mirror.condition;
  o.gravity = Vec2(0, -9.81);
  return o;
}

/// The lattice of the 2-D block nx x ny, lattice (i, j) at index i + nx j, as block() orders 3-D.
inline std::vector<Vec2> block2(int nx, int ny) {
  std::vector<Vec2> x;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) x.emplace_back(l0 * (i + 0.5), l0 * (j + 0.5));
  return x;
}

/// The smallest and largest of `by_id` (values indexed by the block's lattice id) over the
/// lattice column c through the nz layers of `layer` particles each.
inline std::pair<double, double> across_z(const std::vector<double>& by_id, std::size_t c,
                                          std::size_t layer) {
  double lo = by_id[c], hi = by_id[c];
  for (std::size_t k = 1; k < nz; ++k)
    lo = std::min(lo, by_id[c + k * layer]), hi = std::max(hi, by_id[c + k * layer]);
  return {lo, hi};
}

} // namespace fsi::emps::test
