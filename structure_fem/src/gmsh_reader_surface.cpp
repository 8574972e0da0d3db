// Gmsh .msh import of a surface of 3-node triangles (walls for a fluid): the sections parsed as
// for the T6 and T10 meshes (gmsh_sections.cpp), in surface mode.
#include "fsi/core/error.hpp"
#include "gmsh_sections.hpp"
#include "structure_fem/gmsh_reader.hpp"

namespace fsi::fem {

SurfaceMesh read_gmsh_surface(const std::string& path) {
  auto in = gmsh::open_mesh_file(path);
  return read_gmsh_surface(in, path);
}

SurfaceMesh read_gmsh_surface(std::istream& in, const std::string& path) {
  const gmsh::Parsed p = gmsh::parse(in, path, 3, {}, true);
  SurfaceMesh mesh;
  mesh.X = p.X;
  for (const auto& el : p.elements) {
    if (el.type != p.domain_type()) continue;
    mesh.triangles.push_back({el.nodes[0], el.nodes[1], el.nodes[2]});
    mesh.where.push_back(p.at(el.line) + "element " + std::to_string(el.tag));
  }
  if (mesh.triangles.empty())
    throw InputError(path + ": no 3-node triangles (mesh the surface with gmsh -2)");
  return mesh;
}

} // namespace fsi::fem
