#pragma once
// Gmsh .msh import of second-order triangle meshes: format 4.1 (ASCII and binary, `-bin`) and
// ASCII 2.2 (`-format msh22`), as Gmsh writes them.
#include <istream>
#include <string>
#include <vector>

#include "structure_fem/mesh.hpp"

namespace fsi::fem {

/// Reads `path`: 6-node triangles (type 9) form the domain; 3-node lines (type 8) in a 1D
/// physical group become boundary edges tagged with the group's name from $PhysicalNames (edges
/// are re-oriented so the solid is on their left); point elements (type 15) are ignored. Every
/// name in `required_groups` must be a physical group. The result is validated (validate_mesh).
/// Throws InputError `path:line: what` (ASCII), `path: byte N: what` (binary) or `path: what`
/// for malformed input, linear, quadrangle or other element types, nodes off the plane z = 0
/// (each with the gmsh option that fixes it), missing groups and the mesh problems of
/// validate_mesh. Tokens quoted in messages are capped at 40 characters and escaped.
Mesh read_gmsh(const std::string& path, const std::vector<std::string>& required_groups = {});

/// The same from a stream; `path` names it in messages and in Mesh::source.
Mesh read_gmsh(std::istream& in, const std::string& path,
               const std::vector<std::string>& required_groups = {});

} // namespace fsi::fem
