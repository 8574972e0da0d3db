// Gmsh surface meshes (3-node triangles from gmsh -2 on a 3-D geometry) read for fluid walls: the
// shipped 3-D tank's surface (its area that of the box to round-off) and the meshes refused.
#include <catch2/catch.hpp>

#include <string>

#include <Eigen/Geometry>

#include "input_error.hpp"
#include "structure_fem/gmsh_reader.hpp"

using namespace fsi::fem;
using Catch::Contains;

namespace {

std::string data(const std::string& name) {
  return std::string(FSI_TEST_DATA) + "/gmsh/" + name;
}

} // namespace

TEST_CASE("fem: Gmsh surface reader: the 3-D tank's inside as 116 triangles",
          "[structure_fem][gmsh]") {
  const std::string path = FSI_SOURCE_DIR "/data/meshes/hydrostatic_tank_emps_3d.msh";
  const SurfaceMesh mesh = read_gmsh_surface(path);
  REQUIRE(mesh.triangles.size() == 116);
  CHECK(mesh.X.size() == 60);
  double area = 0.0;
  for (const auto& t : mesh.triangles)
    area += 0.5 * (mesh.X[static_cast<std::size_t>(t[1])] - mesh.X[static_cast<std::size_t>(t[0])])
                      .cross(mesh.X[static_cast<std::size_t>(t[2])] -
                             mesh.X[static_cast<std::size_t>(t[0])])
                      .norm();
  CHECK_THAT(area, Catch::Matchers::WithinRel(2.0 * (0.2 * 0.4 * 2.0 + 0.2 * 0.2), 1e-13));
  CHECK_THAT(mesh.where.front(), Contains(path + ":") && Contains(": element 1"));
}

TEST_CASE("fem: Gmsh surface reader: second-order and volume meshes are refused",
          "[structure_fem][gmsh]") {
  CHECK_THAT(message_of([] { read_gmsh_surface(data("cube_41.msh")); }),
             Contains("cube_41.msh:") &&
                 Contains("(type 9): second-order element: need 3-node triangles (type 2): mesh "
                          "with gmsh -2 (order 1)"));
  CHECK_THAT(message_of([] { read_gmsh_surface(data("cube_order1.msh")); }),
             Contains("(type 4): tetrahedron: a volume mesh: need the surface only, gmsh -2"));
  CHECK_THAT(message_of([] { read_gmsh_surface(data("plate_41.msh")); }),
             Contains("(type 8): second-order element"));
}
