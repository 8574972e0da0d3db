#pragma once
// Fluid -> structure force projection (EMPS-ERP-FEM paper, eqs. 53-59), mesh-agnostic.
//
// An interface edge is a quadratic (3-node) edge given by interface-node indices
// (corner, mid, corner) with parent coordinate xi in [-1, 1] (-1 at nodes[0], 0 at nodes[1],
// +1 at nodes[2]). A point load at xi is distributed with the edge's quadratic shape functions
//   N0 = xi (xi - 1) / 2,  N1 = 1 - xi^2,  N2 = xi (xi + 1) / 2          (eq. 58)
// so the total force is conserved exactly, and the total moment is conserved exactly when the
// load acts at the isoparametric point x(xi) = sum_k N_k(xi) x_k. A uniform traction splits
// 1/6, 2/3, 1/6 on a straight edge with the mid node at its centre.
//
// Sign convention: the input forces are the forces ON THE STRUCTURE, i.e. already -f_wall,i of
// eq. 58 (f_wall,i is the force of the walls on fluid particle i, eq. 52). The adapter negates.
#include <array>
#include <cstddef>
#include <span>

#include "coupling/interface.hpp"

namespace fsi::coupling {

struct InterfaceEdge {
  std::array<std::size_t, 3> nodes; ///< interface-node indices: corner, mid, corner
};

struct PointLoad {
  std::size_t edge; ///< index into the edge list
  double xi;        ///< parent coordinate on the edge, in [-1, 1]
  Vec2 f;           ///< force on the structure [N per unit thickness]
};

/// N0, N1, N2 at xi.
inline std::array<double, 3> edge_shape_functions(double xi) {
  return {0.5 * xi * (xi - 1.0), 1.0 - xi * xi, 0.5 * xi * (xi + 1.0)};
}

/// Isoparametric point x(xi) = sum_k N_k(xi) x_k of an edge with node positions x0, x1, x2.
inline Vec2 edge_point(const Vec2& x0, const Vec2& x1, const Vec2& x2, double xi) {
  const auto n = edge_shape_functions(xi);
  return n[0] * x0 + n[1] * x1 + n[2] * x2;
}

/// Add the nodal equivalents of `loads` to out.f (eq. 58; not cleared first). out.f must already
/// have one entry per interface node. The result is deterministic for a given input whatever
/// the thread count: loads are split in a fixed number of chunks, each accumulated in its own
/// buffer, and the buffers are added in chunk order. Preconditions (asserted): edge indices in
/// range, node indices < out.size(), xi in [-1, 1].
void project_point_loads(std::span<const InterfaceEdge> edges, std::span<const PointLoad> loads,
                         InterfaceLoads& out);

} // namespace fsi::coupling
