// Gmsh .msh reader: a valid fixture and one fixture per class of malformed input; the formats
// Gmsh writes (ASCII 4.1, binary 4.1, ASCII 2.2); messages with the fix and without line 0.
#include <catch2/catch.hpp>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

#include "fsi/core/error.hpp"
#include "input_error.hpp"
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

namespace {
std::string gmsh_fixture(const std::string& name) {
  return fixture("gmsh/" + name);
}

/// Sum of the straight-sided areas of the triangles (corners 0, 1, 2).
double mesh_area(const Mesh& mesh) {
  double area = 0.0;
  for (const auto& el : mesh.elements) {
    const auto a = mesh.X[static_cast<std::size_t>(el[0])];
    const auto b = mesh.X[static_cast<std::size_t>(el[1])];
    const auto c = mesh.X[static_cast<std::size_t>(el[2])];
    area += 0.5 * ((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
  }
  return area;
}
} // namespace

// data/gmsh/plate.geo meshed by Gmsh 4.8.4 (Debian) with `gmsh plate.geo -2 -order 2` and
// `-format msh41`, `-format msh41 -bin`, `-format msh22`: the same mesh three times.
TEST_CASE("fem: Gmsh reader: ASCII 4.1, binary 4.1 and ASCII 2.2 from Gmsh give the same mesh",
          "[structure_fem][gmsh]") {
  const std::vector<std::string> groups = {"clamped", "interface", "solid"};
  const Mesh ascii = read_gmsh(gmsh_fixture("plate_41.msh"), groups);
  const Mesh binary = read_gmsh(gmsh_fixture("plate_41_bin.msh"), groups);
  const Mesh msh22 = read_gmsh(gmsh_fixture("plate_22.msh"), groups);
  CHECK(ascii.num_nodes() == 57);
  CHECK(ascii.num_elements() == 22);
  CHECK(mesh_area(ascii) == Approx(2.0).epsilon(1e-12)); // the 2 m x 1 m plate
  // Curve 4 (clamped) and curves 2, 3 (interface) of plate.geo, 0.5 m elements.
  CHECK(ascii.edges_with_tag("clamped").size() == 2);
  CHECK(ascii.edges_with_tag("interface").size() == 6);
  for (const Mesh* other : {&binary, &msh22}) {
    REQUIRE(other->num_nodes() == ascii.num_nodes());
    REQUIRE(other->num_elements() == ascii.num_elements());
    CHECK(other->elements == ascii.elements);
    CHECK(other->element_label == ascii.element_label);
    CHECK(other->node_label == ascii.node_label);
    double largest = 0.0; // ASCII prints 16 digits, binary holds every bit
    for (std::size_t i = 0; i < ascii.X.size(); ++i)
      largest = std::max(largest, (other->X[i] - ascii.X[i]).norm());
    CHECK(largest <= 1e-15);
    REQUIRE(other->edges.size() == ascii.edges.size());
    for (std::size_t i = 0; i < ascii.edges.size(); ++i) {
      CHECK(other->edges[i].nodes == ascii.edges[i].nodes);
      CHECK(other->edges[i].tag == ascii.edges[i].tag);
    }
  }
  CHECK(mesh_area(binary) == Approx(2.0).epsilon(1e-12));
}

TEST_CASE("fem: Gmsh reader: first-order, quadrangle and off-plane meshes say how to fix them",
          "[structure_fem][gmsh]") {
  const std::string order1 = message_of([] { read_gmsh(gmsh_fixture("plate_order1.msh")); });
  CHECK_THAT(order1, Contains("plate_order1.msh:") && Contains("wrong element order") &&
                         Contains("gmsh -2 -order 2"));
  const std::string quad = message_of([] { read_gmsh(gmsh_fixture("plate_quad.msh")); });
  CHECK_THAT(quad, Contains("quadrangle") && Contains("remove Recombine") &&
                       Contains("gmsh -2 -order 2"));
  const std::string z = message_of([] { read_gmsh(gmsh_fixture("plate_z.msh")); });
  CHECK_THAT(z, Contains("plate_z.msh:") && Contains("z = 0.5") && Contains("plane z = 0"));
  // A 3-D mesh read as 2-D is named as such (its tetrahedra), not by its first node off z = 0.
  const std::string cube = message_of([] { read_gmsh(gmsh_fixture("cube_41.msh")); });
  CHECK_THAT(cube, Contains("cube_41.msh:") &&
                       Contains("10-node tetrahedron (type 11): a 3-D mesh: read it as a 3-D "
                                "solid (T10), or mesh a surface at z = 0 with gmsh -2 -order 2"));
  std::istringstream tet("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 1 0 0\n"
                         "3 0 1 0\n4 0 0 1\n$EndNodes\n$Elements\n1\n1 4 2 0 1 1 2 3 4\n"
                         "$EndElements\n");
  CHECK(message_of([&] { read_gmsh(tet, "tet.msh"); }) ==
        "tet.msh:13: element 1: tetrahedron (type 4): a 3-D mesh: read it as a 3-D solid (10-node "
        "tetrahedra, gmsh -3 -order 2), or mesh a surface at z = 0 with gmsh -2 -order 2");
  const std::string bin22 = message_of([] { read_gmsh(gmsh_fixture("plate_22_bin.msh")); });
  CHECK_THAT(bin22, Contains("binary .msh 2.2") && Contains("-format msh41"));
}

TEST_CASE("fem: Gmsh reader: messages never say line 0 and show binary bytes capped and escaped",
          "[structure_fem][gmsh]") {
  std::istringstream empty("");
  CHECK(message_of([&] { read_gmsh(empty, "empty.msh"); }) ==
        "empty.msh: empty file (need a Gmsh .msh file)");
  std::istringstream blank("\n\n  \n");
  CHECK(message_of([&] { read_gmsh(blank, "blank.msh"); }) ==
        "blank.msh: empty file (need a Gmsh .msh file)");
  std::istringstream header("$MeshFormat\n");
  CHECK(message_of([&] { read_gmsh(header, "header.msh"); }) ==
        "header.msh:1: unexpected end of file while reading the format version (truncated file?)");

  // 2,000 bytes of binary garbage where a node count belongs.
  std::string garbage = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n";
  for (int i = 0; i < 2000; ++i) garbage += static_cast<char>(0x80 + (i * 37) % 120);
  std::istringstream bad(garbage);
  const std::string m = message_of([&] { read_gmsh(bad, "garbage.msh"); });
  CHECK_THAT(m, Contains("garbage.msh:5: expected an integer for the number of node blocks") &&
                    Contains("\\x80") && Contains("..."));
  CHECK(m.size() < 300);
  CHECK(std::none_of(m.begin(), m.end(),
                     [](char c) { return static_cast<unsigned char>(c) >= 0x80 || c == '\n'; }));

  // A binary file cut inside its nodes.
  std::ifstream in(gmsh_fixture("plate_41_bin.msh"), std::ios::binary);
  std::string whole{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  std::istringstream cut(whole.substr(0, whole.find("$EndNodes") - 100));
  CHECK(message_of([&] { read_gmsh(cut, "cut.msh"); }) ==
        "cut.msh: unexpected end of file while reading a node coordinate (truncated file?)");
}
