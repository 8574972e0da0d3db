#pragma once
// Gmsh .msh import of second-order triangle (2-D) and tetrahedron (3-D) meshes: format 4.1 (ASCII
// and binary, `-bin`) and ASCII 2.2 (`-format msh22`), as Gmsh writes them.
#include <array>
#include <istream>
#include <string>
#include <vector>

#include "structure_fem/mesh.hpp"
#include "structure_fem/mesh_t10.hpp"

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

/// Reads `path` as a 3-D mesh: 10-node tetrahedra (type 11, Gmsh's node order is shape_t10.hpp's)
/// form the domain; 6-node triangles (type 9) in a 2D physical group (physical surface) become
/// boundary faces tagged with the group's name, oriented out of the tetrahedron they bound (the
/// faces of t10_faces); points (type 15) and 3-node lines (type 8) are ignored, physical volumes
/// accepted. Throws InputError as read_gmsh does, and for 4-node tetrahedra, a 2-D mesh (triangles
/// and no tetrahedra), an inverted (negative volume) or zero-volume element, det J <= 0 inside
/// an element (mid-node far from its edge midpoint), a tagged triangle that is not a face of
/// exactly one tetrahedron, a node no element uses and two nodes at the same place.
TetMesh read_gmsh_t10(const std::string& path,
                      const std::vector<std::string>& required_groups = {});

/// The same from a stream; `path` names it in messages and in TetMesh::source.
TetMesh read_gmsh_t10(std::istream& in, const std::string& path,
                      const std::vector<std::string>& required_groups = {});

/// A surface of flat triangles in 3-D (walls for a fluid, geometry_erp), as read_gmsh_surface
/// reads it: the nodes, the triangles in the file's corner order, and where each is.
struct SurfaceMesh {
  std::vector<Vec3> X;
  std::vector<std::array<int, 3>> triangles; ///< indices into X
  std::vector<std::string> where; ///< per triangle: `PATH:LINE: element TAG` (ASCII) or `PATH: ...`
};

/// Reads `path` as a surface mesh (gmsh -2 on a 3-D geometry): 3-node triangles (type 2) in file
/// order, lines (1) and points (15) ignored; format 4.1 (ASCII or binary) or ASCII 2.2. Throws
/// InputError as read_gmsh does, and for second-order elements, tetrahedra (a volume mesh) and a
/// file without triangles. The surface's own checks (orientation, open edges) are the caller's
/// (geometry_erp's assemble_surface).
SurfaceMesh read_gmsh_surface(const std::string& path);
SurfaceMesh read_gmsh_surface(std::istream& in, const std::string& path);

} // namespace fsi::fem
