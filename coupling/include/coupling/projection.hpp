#pragma once
// Fluid -> structure force projection (EMPS-ERP-FEM paper, eqs. 53-59), for any interface the
// structure describes (fsi::BasicInterfaceMesh<D>, core/include/fsi/core/interface_mesh.hpp).
//
// A point load at a parent point of an interface element (xi on an edge in 2-D, (xi, eta) on a
// triangular face in 3-D) is distributed over the element's nodes with that element's own shape
// functions (edge_shape_functions(order, xi), face_shape_functions(order, xi, eta); quadratic for
// FE T6 edges and T10 faces, eq. 58, linear for straight edges and flat faces), so the total force
// is conserved exactly (sum_k N_k = 1), and the total moment exactly when the load acts at the
// isoparametric point x = sum_k N_k x_k. A uniform traction splits 1/6, 2/3, 1/6 on a straight
// quadratic edge with the mid node at its centre.
//
// Sign convention: the input forces are the forces ON THE STRUCTURE, i.e. already -f_wall,i of
// eq. 58 (f_wall,i is the force of the walls on fluid particle i, eq. 52). The adapter negates.
#include <array>
#include <cstddef>
#include <span>
#include <type_traits>

#include "coupling/interface.hpp"
#include "fsi/core/interface_mesh.hpp"

namespace fsi::coupling {

template <int D> struct BasicPointLoad;

template <> struct BasicPointLoad<2> {
  std::size_t edge; ///< index into the interface's edges
  double xi;        ///< parent coordinate on the edge, in [-1, 1]
  Vec2 f;           ///< force on the structure [N per unit thickness]

  std::size_t element() const { return edge; }
  ParentPoint<2> parent() const { return {xi}; }
};

template <> struct BasicPointLoad<3> {
  std::size_t face; ///< index into the interface's faces
  double xi, eta;   ///< parent coordinates on the face: xi, eta >= 0, xi + eta <= 1
  Vec3 f;           ///< force on the structure [N]

  std::size_t element() const { return face; }
  ParentPoint<3> parent() const { return {xi, eta}; }
};

using PointLoad = BasicPointLoad<2>;
using PointLoad3 = BasicPointLoad<3>;

/// Add the nodal equivalents of `loads` to out.f (eq. 58; not cleared first). out.f must already
/// have one entry per interface node. The result is deterministic for a given input whatever
/// the thread count: loads are split in a fixed number of chunks, each accumulated in its own
/// buffer, and the buffers are added in chunk order. Preconditions (asserted): element indices
/// in range, node indices < out.size(), parent points on the parent element. D is deduced from
/// the mesh, so `loads` may be anything that converts to the span (a std::vector, say).
template <int D>
void project_point_loads(const BasicInterfaceMesh<D>& mesh,
                         std::type_identity_t<std::span<const BasicPointLoad<D>>> loads,
                         BasicInterfaceLoads<D>& out);

extern template void project_point_loads(const InterfaceMesh&, std::span<const PointLoad>,
                                         InterfaceLoads&);
extern template void project_point_loads(const InterfaceMesh3&, std::span<const PointLoad3>,
                                         InterfaceLoads3&);

} // namespace fsi::coupling
