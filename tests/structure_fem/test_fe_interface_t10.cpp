// The coupling interface a T10 mesh describes (fem::interface_of): its tagged boundary faces as
// order-2 interface faces, untagged faces left out, normals out of the solid, each FE node once
// at its own position (NCR), the whole wetted area; on the box mesher's box and on a Gmsh cube.
#include <catch2/catch.hpp>

#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "input_error.hpp"
#include "structure_fem/box_mesher.hpp"
#include "structure_fem/gmsh_reader.hpp"
#include "structure_fem/interface_mesh.hpp"

using fsi::Vec3;
using namespace fsi::fem;

namespace {

/// (x1 - x0) x (x2 - x0) of interface face f: twice its area along its normal (flat faces).
Vec3 area_normal(const FeInterface3& fi, std::size_t f) {
  const auto& k = fi.mesh.faces[f];
  const auto& X = fi.mesh.X0;
  return (X[k[1]] - X[k[0]]).cross(X[k[2]] - X[k[0]]);
}

/// Checks what holds for any mesh and tags; returns the interface's total area.
double check_interface(const TetMesh& tets, const FeInterface3& fi,
                       const std::vector<std::string>& tags, const Vec3& centre) {
  const auto& m = fi.mesh;
  CHECK(m.order == 2);
  REQUIRE(fi.fe_node.size() == m.node_count());
  // The tagged faces in tag order, then mesh order, node by node; each FE node once, at the
  // position of its interface node (distance 0).
  std::vector<BoundaryFace> tagged;
  std::set<int> tagged_nodes;
  for (const auto& tag : tags) {
    const auto faces = tets.faces_with_tag(tag);
    tagged.insert(tagged.end(), faces.begin(), faces.end());
    for (int K : tets.node_set(tag)) tagged_nodes.insert(K);
  }
  REQUIRE(m.faces.size() == tagged.size());
  for (std::size_t f = 0; f < tagged.size(); ++f)
    for (std::size_t i = 0; i < 6; ++i) CHECK(fi.fe_node[m.faces[f][i]] == tagged[f].nodes[i]);
  CHECK(std::set<int>(fi.fe_node.begin(), fi.fe_node.end()) == tagged_nodes);
  CHECK(tagged_nodes.size() == fi.fe_node.size());
  double largest_distance = 0.0;
  for (std::size_t k = 0; k < m.node_count(); ++k)
    largest_distance = std::max(largest_distance,
                                (m.X0[k] - tets.X[static_cast<std::size_t>(fi.fe_node[k])]).norm());
  CHECK(largest_distance == 0.0);
  // Interface nodes numbered in order of first appearance.
  std::size_t next = 0;
  for (const auto& face : m.faces)
    for (std::size_t k : face)
      if (k >= next) CHECK(k == next++);
  double area = 0.0;
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    const Vec3 n = area_normal(fi, f);
    const Vec3 centroid = fsi::face_point(m, m.X0, f, 1.0 / 3.0, 1.0 / 3.0);
    CHECK(n.dot(centroid - centre) > 0.0); // out of the solid
    area += 0.5 * n.norm();
  }
  return area;
}

} // namespace

TEST_CASE("fem: T10 interface of a box's tagged sides", "[fem][interface][3d]") {
  const BoxMeshOptions o{{0.5, -1.0, 2.0}, {2.0, 0.3, 0.7}, {4, 2, 3}};
  const TetMesh tets = make_box_mesh(o);
  const std::vector<std::string> tags{"x_max", "z_min", "y_max"};
  const FeInterface3 fi = interface_of(tets, tags);
  const Vec3 centre = o.origin + 0.5 * o.size;
  const double area = check_interface(tets, fi, tags, centre);
  const double expected = 0.3 * 0.7 + 2.0 * 0.3 + 2.0 * 0.7;
  WARN("T10 interface of 3 box sides: area " << area << " m^2, relative error "
                                             << (area - expected) / expected);
  CHECK(std::abs(area - expected) <= 1e-14 * expected);
  CHECK(fi.mesh.faces.size() == 2u * (2 * 3 + 4 * 2 + 4 * 3));
  // Untagged sides left out: each face lies on a tagged side, its unit normal that side's.
  const Vec3 hi = o.origin + o.size;
  for (std::size_t f = 0; f < fi.mesh.faces.size(); ++f) {
    const Vec3 n = area_normal(fi, f).normalized();
    const Vec3 c = fsi::face_point(fi.mesh, fi.mesh.X0, f, 1.0 / 3.0, 1.0 / 3.0);
    const auto on = [&](double c_d, double side, const Vec3& normal) {
      return std::abs(c_d - side) <= 1e-14 && (n - normal).norm() <= 1e-15;
    };
    const bool x_max = on(c.x(), hi.x(), Vec3::UnitX());
    const bool z_min = on(c.z(), o.origin.z(), -Vec3::UnitZ());
    const bool y_max = on(c.y(), hi.y(), Vec3::UnitY());
    CHECK(int(x_max) + int(z_min) + int(y_max) == 1);
  }
}

TEST_CASE("fem: T10 interface of a Gmsh cube's loaded face", "[fem][interface][3d][gmsh]") {
  const TetMesh tets =
      read_gmsh_t10(std::string(FSI_TEST_DATA) + "/gmsh/cube_41.msh", {"clamped", "loaded"});
  const FeInterface3 fi = interface_of(tets, {"loaded"});
  const double area = check_interface(tets, fi, {"loaded"}, Vec3(0.5, 0.5, 0.5));
  WARN("T10 interface of the Gmsh cube's loaded face: area - 1 = " << area - 1.0);
  CHECK(std::abs(area - 1.0) <= 1e-15);
  for (const Vec3& X : fi.mesh.X0) CHECK(X.z() == 1.0); // the clamped face z = 0 left out
}

TEST_CASE("fem: T10 interface refuses a tag no face carries", "[fem][interface][3d]") {
  const TetMesh tets = make_box_mesh({});
  CHECK(message_of([&] {
          interface_of(tets, {"x_min", "wetted"});
        }) == "box mesh: no boundary face is tagged \"wetted\"");
}
