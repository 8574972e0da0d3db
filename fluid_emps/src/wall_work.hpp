#pragma once
// The work of a particle's walls beyond a bulk particle's, the load the partition over processes
// balances (issue 47; docs/performance.md "Cost weights"). Per acting face (the nearest wall and
// the planes of a concave edge or corner) a particle costs the face's part of the wall query and
// its mirror terms (eqs. 20, 24-27) besides what a bulk particle costs (pair sums, eqs. 9-11, its
// query, the integration): work = faces x face_work, face_work the instructions of a face-step
// over those of a bulk particle-step, from callgrind counts of two ranks with equal particles and
// unequal faces (scalar kernels). The convex pieces of an obstacle's edges are not counted.
#include "fluid_emps/emps_fluid.hpp"
#include "fsi/core/parallel.hpp"

#include <vector>

namespace fsi::emps {

/// Bulk particle-steps per acting face-step: 4,516 / 3,927 instructions in 2-D, 32,643 / 23,327
/// in 3-D (docs/performance.md "Cost weights").
template <int D> inline constexpr double face_work = D == 2 ? 1.15 : 1.40;

/// work[i] = face_work * (faces acting on particle i) for the first n particles, from the last
/// wall query's hits.
template <int D>
void wall_work(const EmpsWalls<D>& walls, std::size_t n, std::vector<double>& work) {
  parallel_for(n, [&](std::size_t i) {
    int faces = 0;
    if constexpr (D == 2)
      for (const auto& face : walls.hits.face) faces += face.segment[i] >= 0 ? 1 : 0;
    else
      for (const auto& face : walls.hits) faces += face.triangle[i] >= 0 ? 1 : 0;
    work[i] = face_work<D> * faces;
  });
}

} // namespace fsi::emps
