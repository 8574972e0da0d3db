#pragma once
// Consistent nodal forces of boundary loads: on T6 edges (node arrays of size 2 * nodes) and on
// T10 faces (size 3 * nodes).
#include <functional>
#include <string>

#include "structure_fem/mesh.hpp"
#include "structure_fem/mesh_t10.hpp"

namespace fsi::fem {

/// Nodal forces of a uniform dead traction t [N/m^2 per unit thickness = N/m per unit length of
/// reference edge] on the edges tagged `tag`: f_K = integral_edge N_K t dS (3-point Gauss; a
/// straight edge gets 1/6, 2/3, 1/6 of its load). Throws InputError if no edge carries the tag.
Vector edge_traction_forces(const Mesh& mesh, const std::string& tag, const Vec2& traction);

/// The same for a dead traction t(X) varying along the edges (e.g. hydrostatic pressure):
/// f_K = integral_edge N_K t(X) dS, 3-point Gauss (exact for t quadratic on a straight edge).
Vector edge_traction_field_forces(const Mesh& mesh, const std::string& tag,
                                  const std::function<Vec2(const Vec2& X)>& traction);

/// Nodal forces of a dead traction t(X) [N/m^2 of reference area] on the 6-node faces tagged
/// `tag`: f_K = integral_face N_K t(X) dA, 6-point rule of degree 4 on the parent triangle.
/// Throws InputError if no face carries the tag.
Vector face_traction_forces(const TetMesh& mesh, const std::string& tag,
                            const std::function<Vec3(const Vec3& X)>& traction);

/// Nodal forces of a dead pressure p(X) [Pa] on the faces tagged `tag`, acting against the
/// reference outward normal: f_K = -integral_face N_K p(X) N dA.
Vector face_pressure_forces(const TetMesh& mesh, const std::string& tag,
                            const std::function<double(const Vec3& X)>& pressure);

} // namespace fsi::fem
