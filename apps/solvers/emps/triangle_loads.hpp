#pragma once
// The 3-D EMPS fluid's wall forces as loads on a structure's interface (EMPS-ERP-FEM paper,
// eqs. 52-59 in 3-D): each particle's force on a flat triangle of an interface face acts on the
// structure as -f at its wall point, shared among the 6-node face's nodes by the face's shape
// functions (erp::InterfaceTriangles::load_weights). The glue between the fluid and the coupler:
// neither library knows the other.
#include "coupling/interface.hpp"
#include "fluid_emps/emps_fluid.hpp"
#include "geometry_erp/interface_triangles.hpp"

namespace fsi::app::emps_plugin {

/// loads.f[k] = -sum of N_k(x_wall) f over the particles' faces on the triangles of `walls`
/// (eqs. 53-59); loads has walls.node_count() nodes afterwards. The loads sum to minus the
/// forces on those triangles (the weights sum to 1).
void project_triangle_forces(const emps::WallForces3& forces, const erp::InterfaceTriangles& walls,
                             coupling::InterfaceLoads3& loads);

} // namespace fsi::app::emps_plugin
