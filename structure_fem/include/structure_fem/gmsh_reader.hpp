#pragma once
// Gmsh .msh 4.1 ASCII import of second-order triangle meshes.
#include <istream>
#include <string>
#include <vector>

#include "structure_fem/mesh.hpp"

namespace fsi::fem {

/// Reads `path`: 6-node triangles (type 9) form the domain; 3-node lines (type 8) in a 1D
/// physical group become boundary edges tagged with the group's name from $PhysicalNames (edges
/// are re-oriented so the solid is on their left); point elements (type 15) are ignored. Every
/// name in `required_groups` must be a physical group. The result is validated (validate_mesh).
/// Throws InputError `path:line: what` for malformed input, linear or other element types,
/// missing groups and the mesh problems of validate_mesh.
Mesh read_gmsh(const std::string& path, const std::vector<std::string>& required_groups = {});

/// The same from a stream; `path` names it in messages and in Mesh::source.
Mesh read_gmsh(std::istream& in, const std::string& path,
               const std::vector<std::string>& required_groups = {});

} // namespace fsi::fem
