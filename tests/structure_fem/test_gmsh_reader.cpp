// Gmsh .msh 4.1 reader: a valid fixture and one fixture per class of malformed input.
#include <catch2/catch.hpp>

#include <string>

#include "fsi/core/error.hpp"
#include "structure_fem/gmsh_reader.hpp"

using namespace fsi::fem;
using Catch::Contains;

namespace {
std::string fixture(const std::string& name) {
  return std::string(FSI_TEST_DATA) + "/" + name;
}
} // namespace

TEST_CASE("fem: Gmsh reader: valid second-order mesh with physical groups",
          "[structure_fem][gmsh]") {
  const Mesh mesh = read_gmsh(fixture("valid.msh"), {"clamped", "interface", "solid"});
  CHECK(mesh.num_nodes() == 15);
  CHECK(mesh.num_elements() == 4);
  CHECK(mesh.edges.size() == 4);
  CHECK(mesh.edges_with_tag("interface").size() == 3);
  CHECK(mesh.node_set("interface") == std::vector<int>{4, 9, 10, 11, 12, 13, 14});
  CHECK(mesh.node_set("clamped") == std::vector<int>{0, 5, 10});
  // The clamped line was written with the solid on its right; it is turned round.
  const auto clamped = mesh.edges_with_tag("clamped").front();
  CHECK(clamped.nodes == std::array<int, 3>{10, 5, 0});
  CHECK(mesh.element_label.back() == 8);
  CHECK(mesh.X[7].x() == 1.0);
  CHECK(mesh.X[7].y() == 0.5);
}

TEST_CASE("fem: Gmsh reader: malformed files throw InputError naming the problem",
          "[structure_fem][gmsh]") {
  CHECK_THROWS_AS(read_gmsh(fixture("inverted_element.msh")), fsi::InputError);
  CHECK_THROWS_WITH(read_gmsh(fixture("inverted_element.msh")), Contains("inverted_element.msh:") &&
                                                                    Contains("element 6") &&
                                                                    Contains("inverted"));
  CHECK_THROWS_WITH(read_gmsh(fixture("duplicate_node.msh")),
                    Contains("node 16") && Contains("duplicate node") && Contains("node 8"));
  CHECK_THROWS_WITH(read_gmsh(fixture("unused_node.msh")),
                    Contains("unused_node.msh:") && Contains("node 16") && Contains("unused node"));
  CHECK_THROWS_WITH(read_gmsh(fixture("linear_triangles.msh")),
                    Contains("linear_triangles.msh:") && Contains("3-node triangle") &&
                        Contains("wrong element order"));
  CHECK_THROWS_WITH(read_gmsh(fixture("missing_interface.msh"), {"clamped", "interface"}),
                    Contains("missing physical group \"interface\""));
  CHECK_THROWS_WITH(read_gmsh(fixture("truncated.msh")),
                    Contains("truncated.msh:") && Contains("unexpected end of file"));
  CHECK_THROWS_WITH(read_gmsh(fixture("no_such_file.msh")), Contains("cannot open"));
}
