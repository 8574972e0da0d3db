// The coupling interface a T6 mesh describes: its tagged edges as order-2 interface edges with the
// solid on the left, each FE node once, the map back to FE nodes, and the whole wetted length.
#include "structure_fem/interface_mesh.hpp"
#include "structure_fem/rectangle_mesher.hpp"

#include <catch2/catch.hpp>

#include <set>

using namespace fsi;
using namespace fsi::fem;
using Catch::Matchers::WithinAbs;

TEST_CASE("fem: interface of a rectangle's tagged sides", "[fem][interface]") {
  RectangleMeshOptions o;
  o.origin = {0.2, 0.0};
  o.width = 0.012;
  o.height = 0.08;
  o.elements_x = 2;
  o.elements_y = 8;
  const Mesh mesh = make_rectangle_mesh(o);
  const FeInterface fi = interface_of(mesh, {"left", "top", "right"});
  const InterfaceMesh& m = fi.mesh;
  CHECK(m.order == 2);
  CHECK(m.edges.size() == 8 + 2 + 8);
  // Each FE node once, at its reference position; 2 per edge plus the two open ends' last node.
  CHECK(m.node_count() == 2 * m.edges.size() + 1);
  CHECK(std::set<int>(fi.fe_node.begin(), fi.fe_node.end()).size() == fi.fe_node.size());
  for (std::size_t k = 0; k < m.node_count(); ++k)
    CHECK(m.X0[k] == mesh.X[static_cast<std::size_t>(fi.fe_node[k])]);
  double length = 0.0;
  const Vec2 centre(0.206, 0.04);
  for (std::size_t e = 0; e < m.edges.size(); ++e) {
    const auto [a, mid, b] = m.edges[e];
    const Vec2 xa = m.X0[a], xb = m.X0[b];
    length += (xb - xa).norm();
    CHECK((m.X0[mid] - 0.5 * (xa + xb)).norm() < 1e-15); // straight edges, mid node at the centre
    // The solid on the left of a -> b: the centre is to the left.
    const Vec2 t = xb - xa;
    CHECK(t.x() * (centre.y() - xa.y()) - t.y() * (centre.x() - xa.x()) > 0.0);
  }
  CHECK_THAT(length, WithinAbs(0.08 + 0.012 + 0.08, 1e-14));
}
