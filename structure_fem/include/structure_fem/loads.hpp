#pragma once
// Consistent nodal forces of boundary loads, as node arrays of size 2 * nodes.
#include <functional>
#include <string>

#include "structure_fem/mesh.hpp"

namespace fsi::fem {

/// Nodal forces of a uniform dead traction t [N/m^2 per unit thickness = N/m per unit length of
/// reference edge] on the edges tagged `tag`: f_K = integral_edge N_K t dS (3-point Gauss; a
/// straight edge gets 1/6, 2/3, 1/6 of its load). Throws InputError if no edge carries the tag.
Vector edge_traction_forces(const Mesh& mesh, const std::string& tag, const Vec2& traction);

/// The same for a dead traction t(X) varying along the edges (e.g. hydrostatic pressure):
/// f_K = integral_edge N_K t(X) dS, 3-point Gauss (exact for t quadratic on a straight edge).
Vector edge_traction_field_forces(const Mesh& mesh, const std::string& tag,
                                  const std::function<Vec2(const Vec2& X)>& traction);

} // namespace fsi::fem
