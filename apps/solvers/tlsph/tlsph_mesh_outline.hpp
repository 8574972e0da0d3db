#pragma once
// A Gmsh region of a TL-SPH solid (structures[].region.file): the boundary of the T6 mesh that
// structure_fem's reader returns, as one counter-clockwise polygon with a tag per edge, filled
// with particles like a polygon region.
#include "fsi/core/types.hpp"
#include "structure_fem/mesh.hpp"

#include <string>
#include <vector>

namespace fsi::app::tlsph_plugin {

struct MeshOutline {
  std::vector<Vec2> outline;     ///< counter-clockwise (solid on the left)
  std::vector<std::string> tags; ///< tag of edge outline[i] -> outline[i + 1 mod n]
};

/// The element sides on no other element, walked corner, mid-node, corner with the solid on the
/// left; each side tagged with the physical group of its line element ("boundary" if it has
/// none, as a polygon's default); consecutive collinear edges of one tag merged (a straight
/// side is one edge, as in a polygon); the loop starts at its lowest, then leftmost vertex.
/// Throws InputError naming the mesh when the boundary is not one closed loop (a hole or a
/// second body: more than one loop; a node where the boundary touches itself) or a side is
/// in two physical groups.
MeshOutline mesh_outline(const fem::Mesh& mesh);

} // namespace fsi::app::tlsph_plugin
