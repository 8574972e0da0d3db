#pragma once
// The coupling interface of a structure, described by the structure solver that owns it
// (EMPS-ERP-FEM paper, eqs. 47-59; RKGC paper, sec. 2.3). Every fluid builds its own boundary
// from it (EMPS: ERP polygons through NCR; SPH: boundary particles) and every mapping between
// interface loads or motion and points on the interface goes through edge_shape_functions() in
// 2-D and face_shape_functions() in 3-D, the one copy of each.
//
// BasicInterfaceMesh<D> (docs/architecture.md, "Two and three dimensions"): its elements are
// edges in 2-D (InterfaceMesh) and triangular faces in 3-D (InterfaceMesh3).
// Interface node k is the k-th entry of InterfaceMotion / InterfaceLoads (coupling/interface.hpp).
//
// Edge convention (D = 2): (a, m, b) with parent coordinate xi = -1 at a, 0 at m, +1 at b; the
// SOLID is on the LEFT of a -> b (counter-clockwise around the solid), so the fluid is on the
// right. Order 2 (FE T6 edges): m is the mid-side node. Order 1 (TL-SPH surface particles):
// straight edges, m is unused and set equal to a.
//
// Face convention (D = 3): corners 0, 1, 2, then mid-side nodes 3 (0-1), 4 (1-2), 5 (2-0) (Gmsh's
// 6-node triangle, the T10 boundary faces of structure_fem/mesh_t10.hpp), parent coordinates
// (xi, eta) on {xi, eta >= 0, xi + eta <= 1} with corner 0 at (0, 0), 1 at (1, 0), 2 at (0, 1).
// The corners run counter-clockwise seen from the fluid: (x1 - x0) x (x2 - x0) points out of the
// solid, into the fluid. Order 2 (FE T10 faces): curved 6-node triangles. Order 1 (TL-SPH surface
// particles): flat 3-node triangles, the mid-side slots are unused and set equal to corner 0.
//
// A particle solid may add its particles themselves as the last nodes (on no element), for a
// particle fluid to take as its boundary (RKGC paper, sec. 2.3: the fluid sees the solid's
// particles); a fluid that uses only the elements leaves them be.
#include "fsi/core/types.hpp"

#include <array>
#include <cstddef>
#include <vector>

namespace fsi {

template <int D> struct BasicInterfaceMesh;

template <> struct BasicInterfaceMesh<2> {
  int order = 2;                                 ///< 1 or 2
  std::vector<Vec2> X0;                          ///< reference positions of the nodes [m]
  std::vector<std::array<std::size_t, 3>> edges; ///< node indices (a, m, b)
  /// Volumes [m^2] of the particle nodes: the last particle_volume.size() nodes, on no edge.
  std::vector<double> particle_volume;

  std::size_t node_count() const { return X0.size(); }
  /// Index of the first particle node (node_count() when there is none).
  std::size_t first_particle() const { return X0.size() - particle_volume.size(); }
  /// The elements, for code written for both dimensions.
  const auto& elements() const { return edges; }
};

template <> struct BasicInterfaceMesh<3> {
  int order = 2;                                 ///< 1 or 2
  std::vector<Vec3> X0;                          ///< reference positions of the nodes [m]
  std::vector<std::array<std::size_t, 6>> faces; ///< node indices (corners, then mid-sides)
  /// Volumes [m^3] of the particle nodes: the last particle_volume.size() nodes, on no face.
  std::vector<double> particle_volume;

  std::size_t node_count() const { return X0.size(); }
  /// Index of the first particle node (node_count() when there is none).
  std::size_t first_particle() const { return X0.size() - particle_volume.size(); }
  /// The elements, for code written for both dimensions.
  const auto& elements() const { return faces; }
};

using InterfaceMesh = BasicInterfaceMesh<2>;
using InterfaceMesh3 = BasicInterfaceMesh<3>;

/// Parent coordinates of a point on an element: (xi) on an edge, (xi, eta) on a face.
template <int D> using ParentPoint = std::array<double, D - 1>;

/// Shape functions (N_a, N_m, N_b) of an edge of `order` at xi in [-1, 1]; they sum to 1.
/// Order 2: N_a = xi (xi - 1) / 2, N_m = 1 - xi^2, N_b = xi (xi + 1) / 2 (eq. 58).
/// Order 1: N_a = (1 - xi) / 2, N_m = 0, N_b = (1 + xi) / 2.
inline std::array<double, 3> edge_shape_functions(int order, double xi) {
  if (order == 1) return {0.5 * (1.0 - xi), 0.0, 0.5 * (1.0 + xi)};
  return {0.5 * xi * (xi - 1.0), 1.0 - xi * xi, 0.5 * xi * (xi + 1.0)};
}

/// Shape functions (N_0, ..., N_5) of a face of `order` at (xi, eta); they sum to 1. With the area
/// coordinates L0 = 1 - xi - eta, L1 = xi, L2 = eta (the 6-node triangle of eqs. 37-39):
/// order 2: N_i = L_i (2 L_i - 1) at the corners, N_3 = 4 L0 L1, N_4 = 4 L1 L2, N_5 = 4 L2 L0;
/// order 1: N_i = L_i at the corners, 0 at the mid-side slots.
inline std::array<double, 6> face_shape_functions(int order, double xi, double eta) {
  const double L0 = 1.0 - xi - eta, L1 = xi, L2 = eta;
  if (order == 1) return {L0, L1, L2, 0.0, 0.0, 0.0};
  return {L0 * (2.0 * L0 - 1.0), L1 * (2.0 * L1 - 1.0), L2 * (2.0 * L2 - 1.0),
          4.0 * L0 * L1,         4.0 * L1 * L2,         4.0 * L2 * L0};
}

/// The shape functions of `mesh`'s elements at the parent point s, for code written for both
/// dimensions.
inline std::array<double, 3> element_shape_functions(const InterfaceMesh& mesh, ParentPoint<2> s) {
  return edge_shape_functions(mesh.order, s[0]);
}
inline std::array<double, 6> element_shape_functions(const InterfaceMesh3& mesh, ParentPoint<3> s) {
  return face_shape_functions(mesh.order, s[0], s[1]);
}

/// Whether s lies on the parent element: xi in [-1, 1]; xi, eta >= 0 and xi + eta <= 1.
inline bool in_parent_element(ParentPoint<2> s) {
  return s[0] >= -1.0 && s[0] <= 1.0;
}
inline bool in_parent_element(ParentPoint<3> s) {
  return s[0] >= 0.0 && s[1] >= 0.0 && s[0] + s[1] <= 1.0;
}

/// x(xi) = sum_k N_k(xi) x_k on edge e, with node positions x (any state: reference or current).
inline Vec2 edge_point(const InterfaceMesh& mesh, const std::vector<Vec2>& x, std::size_t e,
                       double xi) {
  const auto n = edge_shape_functions(mesh.order, xi);
  const auto& k = mesh.edges[e];
  return n[0] * x[k[0]] + n[1] * x[k[1]] + n[2] * x[k[2]];
}

/// x(xi, eta) = sum_k N_k(xi, eta) x_k on face f, with node positions x (any state).
inline Vec3 face_point(const InterfaceMesh3& mesh, const std::vector<Vec3>& x, std::size_t f,
                       double xi, double eta) {
  const auto n = face_shape_functions(mesh.order, xi, eta);
  const auto& k = mesh.faces[f];
  Vec3 p = Vec3::Zero();
  for (std::size_t i = 0; i < 6; ++i) p += n[i] * x[k[i]];
  return p;
}

} // namespace fsi
