// Gmsh .msh reader of T10 meshes: a hand-made two-tetrahedron mesh written by the test as ASCII
// 4.1, binary 4.1 and ASCII 2.2; a unit cube meshed by Gmsh in the three formats; one message
// (with its line) per kind of bad mesh.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <iomanip>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include "fsi/core/error.hpp"
#include "input_error.hpp"
#include "structure_fem/element_t10.hpp"
#include "structure_fem/gmsh_reader.hpp"

using namespace fsi::fem;
using Catch::Contains;

namespace {

struct Element {
  int dim, entity, type; // entity: physical group 1 "clamped", 2 "loaded" (surfaces), 3 (volume)
  long tag;
  std::vector<long> nodes;
};

struct Fixture {
  std::vector<fsi::Vec3> X;
  std::vector<Element> elements;
};

/// Tetrahedra 1 (A, B, C, D) and 2 (A, C, B, E) share face ABC; E = (0, 0, -1) is below it. Face
/// "clamped" (A, E, B) is written outward, face "loaded" (B, D, C) inward.
Fixture two_tets() {
  Fixture f;
  f.X = {{0, 0, 0},     {1, 0, 0},     {0, 1, 0},      {0, 0, 1},     {0, 0, -1},
         {0.5, 0, 0},   {0.5, 0.5, 0}, {0, 0.5, 0},    {0, 0, 0.5},   {0, 0.5, 0.5},
         {0.5, 0, 0.5}, {0, 0, -0.5},  {0, 0.5, -0.5}, {0.5, 0, -0.5}}; // A..E, then mid-nodes
  f.elements = {{2, 1, 9, 3, {1, 5, 2, 12, 14, 6}},
                {2, 2, 9, 4, {2, 4, 3, 11, 10, 7}},
                {3, 3, 11, 1, {1, 2, 3, 4, 6, 7, 8, 9, 10, 11}},
                {3, 3, 11, 2, {1, 3, 2, 5, 8, 7, 6, 12, 14, 13}}};
  return f;
}

const char* const kNames = "$PhysicalNames\n3\n2 1 \"clamped\"\n2 2 \"loaded\"\n3 3 \"solid\"\n"
                           "$EndPhysicalNames\n";

/// ASCII 4.1, one element per block; element i is on line 51 + 2 i (with 14 nodes).
std::string ascii41(const Fixture& f) {
  std::ostringstream s;
  s << std::setprecision(17) << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n" << kNames;
  s << "$Entities\n0 0 2 1\n1 0 0 -1 1 1 1 1 1 0\n2 0 0 -1 1 1 1 1 2 0\n"
       "1 0 0 -1 1 1 1 1 3 0\n$EndEntities\n";
  const std::size_t n = f.X.size();
  s << "$Nodes\n1 " << n << " 1 " << n << "\n3 1 0 " << n << "\n";
  for (std::size_t i = 0; i < n; ++i) s << i + 1 << "\n";
  for (const auto& x : f.X) s << x.x() << " " << x.y() << " " << x.z() << "\n";
  s << "$EndNodes\n$Elements\n" << f.elements.size() << " " << f.elements.size() << " 1 4\n";
  for (const auto& e : f.elements) {
    s << e.dim << " " << e.entity << " " << e.type << " 1\n" << e.tag;
    for (long k : e.nodes) s << " " << k;
    s << "\n";
  }
  s << "$EndElements\n";
  return s.str();
}

/// Little-endian bytes of a value (int: 4, size_t and double: 8).
template <class T> std::string bytes(T v) {
  std::string b(sizeof v, '\0');
  std::memcpy(b.data(), &v, sizeof v);
  return b;
}

/// Binary 4.1 (gmsh -bin): the same sections with ints, size_ts and doubles.
std::string binary41(const Fixture& f) {
  using S = std::uint64_t;
  using I = std::int32_t;
  std::string s = "$MeshFormat\n4.1 1 8\n" + bytes<I>(1) + "\n$EndMeshFormat\n" + kNames;
  s += "$Entities\n" + bytes<S>(0) + bytes<S>(0) + bytes<S>(2) + bytes<S>(1);
  for (const auto& [tag, physical] : {std::pair<I, I>{1, 1}, {2, 2}, {1, 3}}) {
    s += bytes<I>(tag);
    for (const double b : {0.0, 0.0, -1.0, 1.0, 1.0, 1.0}) s += bytes(b);
    s += bytes<S>(1) + bytes<I>(physical) + bytes<S>(0);
  }
  const S n = f.X.size();
  s += "\n$EndEntities\n$Nodes\n" + bytes(S{1}) + bytes(n) + bytes(S{1}) + bytes(n);
  s += bytes<I>(3) + bytes<I>(1) + bytes<I>(0) + bytes(n);
  for (S i = 1; i <= n; ++i) s += bytes(i);
  for (const auto& x : f.X) s += bytes(x.x()) + bytes(x.y()) + bytes(x.z());
  const S m = f.elements.size();
  s += "\n$EndNodes\n$Elements\n" + bytes(m) + bytes(m) + bytes(S{1}) + bytes(S{4});
  for (const auto& e : f.elements) {
    s += bytes<I>(e.dim) + bytes<I>(e.entity) + bytes<I>(e.type) + bytes(S{1});
    s += bytes(static_cast<S>(e.tag));
    for (long k : e.nodes) s += bytes(static_cast<S>(k));
  }
  return s + "\n$EndElements\n";
}

/// ASCII 2.2: each element with its tags (physical group, elementary entity).
std::string ascii22(const Fixture& f) {
  std::ostringstream s;
  s << std::setprecision(17) << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n" << kNames;
  s << "$Nodes\n" << f.X.size() << "\n";
  for (std::size_t i = 0; i < f.X.size(); ++i)
    s << i + 1 << " " << f.X[i].x() << " " << f.X[i].y() << " " << f.X[i].z() << "\n";
  s << "$EndNodes\n$Elements\n" << f.elements.size() << "\n";
  for (const auto& e : f.elements) {
    s << e.tag << " " << e.type << " 2 " << e.entity << " " << e.entity;
    for (long k : e.nodes) s << " " << k;
    s << "\n";
  }
  s << "$EndElements\n";
  return s.str();
}

TetMesh read_text(const std::string& text, const std::vector<std::string>& groups = {}) {
  std::istringstream in(text);
  return read_gmsh_t10(in, "t.msh", groups);
}

std::string message_of_text(const std::string& text, const std::vector<std::string>& groups = {}) {
  return message_of([&] { read_text(text, groups); });
}

std::string gmsh_file(const std::string& name) {
  return std::string(FSI_TEST_DATA) + "/gmsh/" + name;
}

/// For each face: its mid-nodes at the midpoints of sides 0-1, 1-2, 2-0 (largest distance
/// returned) and n . (face centroid - centroid of the tetrahedron with its corners) > 0.
double check_faces(const TetMesh& mesh) {
  double off = 0.0;
  auto X = [&](int k) { return mesh.X[static_cast<std::size_t>(k)]; };
  for (const auto& f : mesh.faces) {
    for (int s = 0; s < 3; ++s)
      off = std::max(off, (X(f.nodes[static_cast<std::size_t>(3 + s)]) -
                           0.5 * (X(f.nodes[static_cast<std::size_t>(s)]) +
                                  X(f.nodes[static_cast<std::size_t>((s + 1) % 3)])))
                              .norm());
    const fsi::Vec3 n = (X(f.nodes[1]) - X(f.nodes[0])).cross(X(f.nodes[2]) - X(f.nodes[0]));
    const fsi::Vec3 centroid = (X(f.nodes[0]) + X(f.nodes[1]) + X(f.nodes[2])) / 3.0;
    int tets = 0;
    for (const auto& el : mesh.elements) {
      int shared = 0;
      for (std::size_t c = 0; c < 4; ++c)
        shared += el[c] == f.nodes[0] || el[c] == f.nodes[1] || el[c] == f.nodes[2];
      if (shared < 3) continue;
      ++tets;
      const fsi::Vec3 inside = (X(el[0]) + X(el[1]) + X(el[2]) + X(el[3])) / 4.0;
      CHECK(n.dot(centroid - inside) > 0.0);
    }
    CHECK(tets == 1);
  }
  return off;
}

void check_same(const TetMesh& a, const TetMesh& b) {
  REQUIRE(a.num_nodes() == b.num_nodes());
  double largest = 0.0; // ASCII prints 16 or 17 digits, binary holds every bit
  for (std::size_t i = 0; i < a.X.size(); ++i)
    largest = std::max(largest, (a.X[i] - b.X[i]).norm());
  CHECK(largest <= 1e-15);
  CHECK(a.elements == b.elements);
  REQUIRE(a.faces.size() == b.faces.size());
  for (std::size_t i = 0; i < a.faces.size(); ++i) {
    CHECK(a.faces[i].nodes == b.faces[i].nodes);
    CHECK(a.faces[i].tag == b.faces[i].tag);
  }
}

double volume(const TetMesh& mesh) {
  double v = 0.0;
  for (const auto& el : mesh.elements) {
    TetNodes X;
    for (std::size_t k = 0; k < 10; ++k) X[k] = mesh.X[static_cast<std::size_t>(el[k])];
    v += t10_volume(X);
  }
  return v;
}

} // namespace

TEST_CASE("fem: Gmsh T10 reader: two tetrahedra as ASCII 4.1, binary 4.1 and ASCII 2.2",
          "[structure_fem][gmsh][t10]") {
  const Fixture f = two_tets();
  const TetMesh ascii = read_text(ascii41(f), {"clamped", "loaded", "solid"});
  CHECK(ascii.source == "t.msh");
  CHECK(ascii.num_nodes() == 14);
  CHECK(ascii.X[10] == fsi::Vec3(0.5, 0.0, 0.5));
  CHECK(ascii.elements == std::vector<std::array<int, 10>>{{0, 1, 2, 3, 5, 6, 7, 8, 9, 10},
                                                           {0, 2, 1, 4, 7, 6, 5, 11, 13, 12}});
  REQUIRE(ascii.faces.size() == 2);
  // "clamped" kept as written (outward), "loaded" turned round: B, C, D = face 2 of element 1.
  CHECK(ascii.faces[0].tag == "clamped");
  CHECK(ascii.faces[0].nodes == std::array<int, 6>{0, 4, 1, 11, 13, 5});
  CHECK(ascii.faces[1].tag == "loaded");
  CHECK(ascii.faces[1].nodes == std::array<int, 6>{1, 2, 3, 6, 9, 10});
  CHECK(check_faces(ascii) == 0.0);
  CHECK(volume(ascii) == Approx(1.0 / 3.0).epsilon(1e-15));
  check_same(ascii, read_text(binary41(f)));
  check_same(ascii, read_text(ascii22(f)));
}

// data/gmsh/cube.geo meshed by Gmsh 4.8.4 (Debian) with `gmsh cube.geo -3 -order 2` and
// `-format msh41`, `-format msh41 -bin`, `-format msh22`: the same mesh three times.
TEST_CASE("fem: Gmsh T10 reader: a unit cube from Gmsh in three formats",
          "[structure_fem][gmsh][t10]") {
  const std::vector<std::string> groups = {"clamped", "loaded", "solid"};
  const TetMesh ascii = read_gmsh_t10(gmsh_file("cube_41.msh"), groups);
  CHECK(ascii.num_nodes() == 63);
  CHECK(ascii.num_elements() == 24);
  CHECK(volume(ascii) == Approx(1.0).epsilon(1e-14));
  CHECK(ascii.faces_with_tag("clamped").size() == 4);
  CHECK(ascii.faces_with_tag("loaded").size() == 4);
  for (const auto& face : ascii.faces) { // clamped at z = 0 (normal -z), loaded at z = 1 (+z)
    const double z = face.tag == "clamped" ? 0.0 : 1.0;
    for (int k : face.nodes) CHECK(ascii.X[static_cast<std::size_t>(k)].z() == z);
  }
  CHECK(check_faces(ascii) <= 1e-15);
  check_same(ascii, read_gmsh_t10(gmsh_file("cube_41_bin.msh"), groups));
  check_same(ascii, read_gmsh_t10(gmsh_file("cube_22.msh"), groups));
}

TEST_CASE("fem: Gmsh T10 reader: bad meshes are refused with their file and line",
          "[structure_fem][gmsh][t10]") {
  Fixture linear = two_tets();
  for (auto& e : linear.elements)
    if (e.type == 11) e.type = 4, e.nodes.resize(4);
  CHECK(message_of_text(ascii41(linear)) ==
        "t.msh:55: element 1: 4-node tetrahedron (type 4): wrong element order, need 10-node "
        "tetrahedra (type 11): mesh with gmsh -3 -order 2");

  Fixture inverted = two_tets();
  inverted.elements[3].nodes = {1, 2, 3, 5, 6, 7, 8, 12, 13, 14};
  CHECK(message_of_text(ascii41(inverted)) ==
        "t.msh:57: element 2: inverted element (negative volume: corners 0, 1, 2 clockwise seen "
        "from corner 3)");
  CHECK(message_of_text(binary41(inverted)) ==
        "t.msh: element 2: inverted element (negative volume: corners 0, 1, 2 clockwise seen "
        "from corner 3)");

  Fixture flat = two_tets();
  flat.X[4] = {1.0, 1.0, 0.0}; // E in the plane of A, B, C
  CHECK(message_of_text(ascii41(flat)) == "t.msh:57: element 2: zero-volume element");

  Fixture curved = two_tets();
  curved.X[8] = {0.0, 0.0, 0.2}; // the mid-node of D-A nearer A than the quarter point
  CHECK(message_of_text(ascii41(curved)) ==
        "t.msh:55: element 1: inverted element (det J <= 0 inside; mid-node too far from its "
        "edge midpoint)");

  Fixture swapped = two_tets(); // the last two edge nodes in CalculiX's C3D10 order, not Gmsh's
  std::swap(swapped.elements[2].nodes[8], swapped.elements[2].nodes[9]);
  CHECK(message_of_text(ascii41(swapped)) ==
        "t.msh:55: element 1: inverted element (det J <= 0 inside; mid-node too far from its "
        "edge midpoint)");

  CHECK(message_of_text(ascii41(two_tets()), {"solid", "interface"}) ==
        "t.msh: missing physical group \"interface\" (the file names: clamped, loaded, solid)");

  Fixture off = two_tets();
  off.elements[0].nodes = {1, 5, 4, 12, 10, 9};
  CHECK(message_of_text(ascii41(off)) == "t.msh:51: triangle element 3 is not a face of any "
                                         "tetrahedron");
  Fixture inner = two_tets();
  inner.elements[1].nodes = {1, 2, 3, 6, 7, 8};
  CHECK(message_of_text(ascii41(inner)) == "t.msh:53: triangle element 4 is inside the solid (a "
                                           "face of two tetrahedra), not on its boundary");

  Fixture unknown = two_tets();
  unknown.elements[3].nodes[9] = 15;
  CHECK(message_of_text(ascii41(unknown)) == "t.msh:57: element 2: unknown node 15");
  CHECK_THAT(message_of_text(binary41(unknown)),
             Catch::StartsWith("t.msh: byte ") && Contains(": element 2: unknown node 15"));

  Fixture unused = two_tets();
  unused.X.emplace_back(2.0, 2.0, 2.0);
  CHECK(message_of_text(ascii41(unused)) ==
        "t.msh:48: node 15: unused node (belongs to no element)");
  Fixture twice = two_tets();
  twice.X.push_back(twice.X[0]); // node 15 at A, in element 2 and face "clamped" instead of 1
  twice.elements[0].nodes[0] = 15;
  twice.elements[3].nodes[0] = 15;
  CHECK(message_of_text(ascii41(twice)) ==
        "t.msh:48: node 15: duplicate node (same coordinates as node 1)");

  CHECK(message_of([] { read_gmsh_t10(gmsh_file("plate_41.msh")); }) ==
        gmsh_file("plate_41.msh") +
            ": a 2-D mesh (6-node triangles, no 10-node tetrahedra): read it as a 2-D solid, or "
            "mesh the volume with gmsh -3 -order 2");
  CHECK(message_of([] { read_gmsh_t10(gmsh_file("cube_order1.msh")); }) ==
        gmsh_file("cube_order1.msh") +
            ":89: element 1: 3-node triangle (type 2): wrong element order, need second-order "
            "6-node triangles (type 9): mesh with gmsh -3 -order 2");
}
