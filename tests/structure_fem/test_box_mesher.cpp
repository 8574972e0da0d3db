// The T10 box mesher: positive element volumes summing to the box, every node used, edge nodes
// at their edges' midpoints, and a conforming triangulation (each face shared by two elements or
// on the boundary).
#include <catch2/catch.hpp>

#include <algorithm>
#include <map>

#include "fsi/core/error.hpp"
#include "structure_fem/box_mesher.hpp"
#include "structure_fem/element_t10.hpp"
#include "structure_fem/shape_t10.hpp"

using namespace fsi::fem;
using Catch::Matchers::WithinRel;

TEST_CASE("T10 box mesher: volumes, nodes and a conforming triangulation",
          "[structure_fem][t10][mesh]") {
  const BoxMeshOptions o{{0.5, -1.0, 2.0}, {2.0, 0.3, 0.7}, {3, 2, 4}};
  const TetMesh mesh = make_box_mesh(o);
  REQUIRE(mesh.elements.size() == 6u * 3 * 2 * 4);
  REQUIRE(mesh.X.size() == 7u * 5 * 9);
  std::vector<int> uses(mesh.X.size(), 0);
  std::map<std::array<int, 3>, int> faces; // sorted vertex triple -> elements
  double volume = 0.0;
  for (const auto& el : mesh.elements) {
    TetNodes X;
    for (std::size_t a = 0; a < 10; ++a) {
      X[a] = mesh.X[static_cast<std::size_t>(el[a])];
      ++uses[static_cast<std::size_t>(el[a])];
    }
    for (std::size_t e = 0; e < 6; ++e) {
      const auto [p, q] = t10_edges[e];
      CHECK((X[4 + e] - 0.5 * (X[static_cast<std::size_t>(p)] + X[static_cast<std::size_t>(q)]))
                .norm() < 1e-14);
    }
    const double v = t10_volume(X);
    CHECK_THAT(v, WithinRel(o.size.prod() / static_cast<double>(mesh.elements.size()), 1e-12));
    volume += v;
    for (int skip = 0; skip < 4; ++skip) {
      std::array<int, 3> f{};
      for (int a = 0, i = 0; a < 4; ++a)
        if (a != skip) f[static_cast<std::size_t>(i++)] = el[static_cast<std::size_t>(a)];
      std::sort(f.begin(), f.end());
      ++faces[f];
    }
  }
  CHECK_THAT(volume, WithinRel(o.size.prod(), 1e-13));
  CHECK(std::count(uses.begin(), uses.end(), 0) == 0);
  int boundary = 0;
  for (const auto& [f, n] : faces) {
    CHECK((n == 1 || n == 2));
    boundary += n == 1;
  }
  CHECK(boundary == 2 * 2 * (3 * 2 + 2 * 4 + 3 * 4)); // two triangles per cell face
  CHECK_THROWS_AS(make_box_mesh({{0, 0, 0}, {1, 0, 1}, {1, 1, 1}}), fsi::InputError);
  CHECK_THROWS_AS(make_box_mesh({{0, 0, 0}, {1, 1, 1}, {1, 0, 1}}), fsi::InputError);
}

TEST_CASE("T10 mesh validation refuses inverted elements and bad node indices",
          "[structure_fem][t10][mesh]") {
  const TetMesh good = make_box_mesh({{0.0, 0.0, 0.0}, {1.0, 0.5, 0.5}, {2, 1, 1}});
  CHECK_NOTHROW(validate_mesh(good));
  TetMesh inverted = good;
  std::swap(inverted.elements[3][1], inverted.elements[3][2]); // vertices 1, 2 and their edges
  std::swap(inverted.elements[3][4], inverted.elements[3][6]);
  std::swap(inverted.elements[3][8], inverted.elements[3][9]);
  CHECK_THROWS_WITH(validate_mesh(inverted), Catch::Contains("element 4: det J <= 0"));
  TetMesh out_of_range = good;
  out_of_range.elements[0][7] = static_cast<int>(good.num_nodes());
  CHECK_THROWS_WITH(validate_mesh(out_of_range), Catch::Contains("element 1: node index"));
}
