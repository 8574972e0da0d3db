#pragma once
// The coupling interface of a structure, described by the structure solver that owns it
// (EMPS-ERP-FEM paper, eqs. 47-59; RKGC paper, sec. 2.3). Every fluid builds its own boundary
// from it (EMPS: ERP polygons through NCR; SPH: boundary particles) and every mapping between
// interface loads or motion and points on the interface goes through edge_shape_functions(), the
// one copy of the edge shape functions.
//
// Interface node k is the k-th entry of InterfaceMotion / InterfaceLoads (coupling/interface.hpp).
// Edge convention: (a, m, b) with parent coordinate xi = -1 at a, 0 at m, +1 at b; the SOLID is on
// the LEFT of a -> b (counter-clockwise around the solid), so the fluid is on the right.
// Order 2 (FE T6 edges): m is the mid-side node. Order 1 (TL-SPH surface particles): straight
// edges, m is unused and set equal to a. A particle solid may add its particles themselves as
// the last nodes (on no edge), for a particle fluid to take as its boundary (RKGC paper, sec.
// 2.3: the fluid sees the solid's particles); a fluid that uses only the edges leaves them be.
#include "fsi/core/types.hpp"

#include <array>
#include <cstddef>
#include <vector>

namespace fsi {

struct InterfaceMesh {
  int order = 2;                                 ///< 1 or 2
  std::vector<Vec2> X0;                          ///< reference positions of the nodes [m]
  std::vector<std::array<std::size_t, 3>> edges; ///< node indices (a, m, b)
  /// Volumes [m^2] of the particle nodes: the last particle_volume.size() nodes, on no edge.
  std::vector<double> particle_volume;

  std::size_t node_count() const { return X0.size(); }
  /// Index of the first particle node (node_count() when there is none).
  std::size_t first_particle() const { return X0.size() - particle_volume.size(); }
};

/// Shape functions (N_a, N_m, N_b) of an edge of `order` at xi in [-1, 1]; they sum to 1.
/// Order 2: N_a = xi (xi - 1) / 2, N_m = 1 - xi^2, N_b = xi (xi + 1) / 2 (eq. 58).
/// Order 1: N_a = (1 - xi) / 2, N_m = 0, N_b = (1 + xi) / 2.
inline std::array<double, 3> edge_shape_functions(int order, double xi) {
  if (order == 1) return {0.5 * (1.0 - xi), 0.0, 0.5 * (1.0 + xi)};
  return {0.5 * xi * (xi - 1.0), 1.0 - xi * xi, 0.5 * xi * (xi + 1.0)};
}

/// x(xi) = sum_k N_k(xi) x_k on edge e, with node positions x (any state: reference or current).
inline Vec2 edge_point(const InterfaceMesh& mesh, const std::vector<Vec2>& x, std::size_t e,
                       double xi) {
  const auto n = edge_shape_functions(mesh.order, xi);
  const auto& k = mesh.edges[e];
  return n[0] * x[k[0]] + n[1] * x[k[1]] + n[2] * x[k[2]];
}

} // namespace fsi
