// A T10 mesh's boundary faces taken as a 3-D coupling interface (fsi::InterfaceMesh3): the
// interface's face shape functions are the ones the T10 face loads use (t6_shape), the mid-side
// nodes are where the face node order says, and (x1 - x0) x (x2 - x0) points out of the solid.
#include <catch2/catch.hpp>

#include <random>

#include <Eigen/Geometry>

#include "fsi/core/interface_mesh.hpp"
#include "structure_fem/box_mesher.hpp"
#include "structure_fem/shape_t6.hpp"

using fsi::Vec3;
using namespace fsi::fem;

TEST_CASE("fem: T10 boundary faces as a 3-D interface", "[fem][interface][3d]") {
  const BoxMeshOptions o{{0.5, -1.0, 2.0}, {2.0, 0.3, 0.7}, {2, 2, 1}};
  const TetMesh tets = make_box_mesh(o);
  fsi::InterfaceMesh3 mesh;
  mesh.X0 = tets.X;
  for (const auto& f : tets.faces) {
    std::array<std::size_t, 6> nodes{};
    for (std::size_t k = 0; k < 6; ++k) nodes[k] = static_cast<std::size_t>(f.nodes[k]);
    mesh.faces.push_back(nodes);
  }
  REQUIRE(mesh.faces.size() == 2u * (2 * 2 + 2 * 1 + 2 * 1) * 2);

  std::mt19937 rng(7u);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 100; ++trial) {
    const double xi = u(rng), eta = u(rng) * (1.0 - xi);
    const auto n = fsi::face_shape_functions(2, xi, eta);
    const auto N = t6_shape(xi, eta);
    for (std::size_t k = 0; k < 6; ++k)
      CHECK(std::abs(n[k] - N[static_cast<Eigen::Index>(k)]) <= 1e-15);
  }

  const Vec3 centre = o.origin + 0.5 * o.size;
  const std::array<std::array<double, 2>, 3> mid{{{0.5, 0.0}, {0.5, 0.5}, {0.0, 0.5}}};
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const auto& k = mesh.faces[f];
    const auto& X = mesh.X0;
    for (std::size_t s = 0; s < 3; ++s) { // mid-side node 3 + s halfway from corner s to s + 1
      const Vec3 halfway = 0.5 * (X[k[s]] + X[k[(s + 1) % 3]]);
      CHECK((X[k[3 + s]] - halfway).norm() <= 1e-15);
      CHECK((fsi::face_point(mesh, X, f, mid[s][0], mid[s][1]) - halfway).norm() <= 1e-15);
    }
    const Vec3 normal = (X[k[1]] - X[k[0]]).cross(X[k[2]] - X[k[0]]);
    CHECK(normal.dot(X[k[0]] - centre) > 0.0);
  }
}
