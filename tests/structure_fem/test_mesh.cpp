// Rectangle mesher and mesh validation.
#include <catch2/catch.hpp>

#include <algorithm>

#include "fsi/core/error.hpp"
#include "structure_fem/element_t6.hpp"
#include "structure_fem/rectangle_mesher.hpp"

using namespace fsi::fem;
using Catch::Contains;
using Catch::Matchers::WithinRel;

TEST_CASE("fem: rectangle mesher: counts, tags, orientation", "[structure_fem][mesh]") {
  const Mesh mesh = make_rectangle_mesh({{1.0, 2.0}, 3.0, 0.5, 6, 2});
  CHECK(mesh.num_elements() == 2 * 6 * 2);
  CHECK(mesh.num_nodes() == 13 * 5);
  CHECK(mesh.edges_with_tag("bottom").size() == 6);
  CHECK(mesh.edges_with_tag("left").size() == 2);
  CHECK(mesh.node_set("right").size() == 5);
  double area = 0.0;
  for (const auto& el : mesh.elements) {
    ElementNodes X;
    for (std::size_t k = 0; k < 6; ++k) X[k] = mesh.X[static_cast<std::size_t>(el[k])];
    area += t6_area(X);
  }
  CHECK_THAT(area, WithinRel(1.5, 1e-13));
  // Solid on the left: the outward normal (t_y, -t_x) of every edge points away from the centre.
  const fsi::Vec2 centre(2.5, 2.25);
  for (const auto& e : mesh.edges) {
    const fsi::Vec2 t =
        mesh.X[static_cast<std::size_t>(e.nodes[2])] - mesh.X[static_cast<std::size_t>(e.nodes[0])];
    const fsi::Vec2 n(t.y(), -t.x());
    CHECK(n.dot(mesh.X[static_cast<std::size_t>(e.nodes[1])] - centre) > 0.0);
  }
  CHECK_THROWS_WITH(mesh.node_set("interface"), Contains("interface"));
  CHECK_THROWS_AS(make_rectangle_mesh({{0.0, 0.0}, -1.0, 1.0, 2, 2}), fsi::InputError);
}

TEST_CASE("fem: rectangle mesher, mirrored diagonals: both top corners in two elements, "
          "mirror-symmetric",
          "[structure_fem][mesh]") {
  // The rising split leaves the upper-left corner in one triangle (the Liao plate's failing tip
  // node, docs/validation-history.md); the mirrored one puts each top corner in two and is
  // symmetric about the vertical mid-line.
  const auto elements_at = [](const Mesh& mesh, fsi::Vec2 X) {
    int count = 0;
    for (const auto& el : mesh.elements)
      for (std::size_t k = 0; k < 3; ++k)
        if ((mesh.X[static_cast<std::size_t>(el[k])] - X).norm() < 1e-12) ++count;
    return count;
  };
  RectangleMeshOptions o{{0.6, 0.0}, 0.004, 0.09, 2, 45};
  const Mesh rising = make_rectangle_mesh(o);
  o.diagonals = Diagonals::mirrored;
  const Mesh mirrored = make_rectangle_mesh(o);
  CHECK(elements_at(rising, {0.6, 0.09}) == 1);
  CHECK(elements_at(mirrored, {0.6, 0.09}) == 2);
  CHECK(elements_at(mirrored, {0.604, 0.09}) == 2);
  REQUIRE(mirrored.num_elements() == rising.num_elements());
  CHECK(mirrored.num_nodes() == rising.num_nodes());
  double area = 0.0, smallest = 1.0;
  for (const auto& el : mirrored.elements) {
    ElementNodes X;
    for (std::size_t k = 0; k < 6; ++k) X[k] = mirrored.X[static_cast<std::size_t>(el[k])];
    area += t6_area(X);
    smallest = std::min(smallest, t6_area(X));
  }
  CHECK_THAT(area, WithinRel(0.004 * 0.09, 1e-12));
  CHECK(smallest > 0.0); // every element counter-clockwise
  CHECK_NOTHROW(validate_mesh(mirrored));
  // Each element's mirror image about x = 0.602 is an element (corner sets compared).
  int unmatched = 0;
  for (const auto& el : mirrored.elements) {
    bool found = false;
    for (const auto& other : mirrored.elements) {
      int same = 0;
      for (std::size_t k = 0; k < 3; ++k) {
        const fsi::Vec2 X = mirrored.X[static_cast<std::size_t>(el[k])];
        const fsi::Vec2 image(2.0 * 0.602 - X.x(), X.y());
        for (std::size_t m = 0; m < 3; ++m)
          if ((mirrored.X[static_cast<std::size_t>(other[m])] - image).norm() < 1e-12) ++same;
      }
      found = found || same == 3;
    }
    if (!found) ++unmatched;
  }
  CHECK(unmatched == 0);
}

TEST_CASE("fem: validation rejects a mid-node that inverts the Jacobian", "[structure_fem][mesh]") {
  Mesh mesh = make_rectangle_mesh({{0.0, 0.0}, 1.0, 1.0, 1, 1});
  // Mid-node 1 (bottom edge) moved off the edge midpoint: allowed while det J > 0 ...
  mesh.X[1] = {0.5, 0.1};
  CHECK_NOTHROW(validate_mesh(mesh));
  // ... rejected when det J <= 0 inside the element.
  mesh.X[1] = {0.5, 0.6};
  CHECK_THROWS_WITH(validate_mesh(mesh), Contains("element 1") && Contains("det J"));
}

TEST_CASE("fem: validation rejects a zero-area element", "[structure_fem][mesh]") {
  Mesh mesh;
  mesh.source = "hand-made";
  mesh.X = {{0.0, 0.0}, {1.0, 0.0}, {3.0, 0.0}, {0.5, 0.0}, {2.0, 0.0}, {1.5, 0.0}};
  mesh.elements = {{0, 1, 2, 3, 4, 5}};
  mesh.element_label = {7};
  CHECK_THROWS_WITH(validate_mesh(mesh),
                    Contains("hand-made") && Contains("element 7") && Contains("zero-area"));
}
