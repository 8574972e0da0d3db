#pragma once
// Fluid -> structure force projection (EMPS-ERP-FEM paper, eqs. 53-59), for any interface the
// structure describes (fsi::InterfaceMesh, core/include/fsi/core/interface_mesh.hpp).
//
// A point load at parent coordinate xi on an interface edge is distributed over the edge's
// nodes with that edge's own shape functions (edge_shape_functions(order, xi); quadratic for
// FE T6 edges, eq. 58, linear for straight edges), so the total force is conserved exactly, and
// the total moment exactly when the load acts at the isoparametric point x(xi). A uniform
// traction splits 1/6, 2/3, 1/6 on a straight quadratic edge with the mid node at its centre.
//
// Sign convention: the input forces are the forces ON THE STRUCTURE, i.e. already -f_wall,i of
// eq. 58 (f_wall,i is the force of the walls on fluid particle i, eq. 52). The adapter negates.
#include <array>
#include <cstddef>
#include <span>

#include "coupling/interface.hpp"
#include "fsi/core/interface_mesh.hpp"

namespace fsi::coupling {

struct PointLoad {
  std::size_t edge; ///< index into the interface's edges
  double xi;        ///< parent coordinate on the edge, in [-1, 1]
  Vec2 f;           ///< force on the structure [N per unit thickness]
};

/// Add the nodal equivalents of `loads` to out.f (eq. 58; not cleared first). out.f must already
/// have one entry per interface node. The result is deterministic for a given input whatever
/// the thread count: loads are split in a fixed number of chunks, each accumulated in its own
/// buffer, and the buffers are added in chunk order. Preconditions (asserted): edge indices in
/// range, node indices < out.size(), xi in [-1, 1].
void project_point_loads(const InterfaceMesh& mesh, std::span<const PointLoad> loads,
                         InterfaceLoads& out);

} // namespace fsi::coupling
