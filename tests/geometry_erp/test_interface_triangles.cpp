// Triangle walls from a structure's 3-D interface mesh: NCR (eq. 50), four flat triangles per
// 6-node face with the face's fluid side, parent points, the face shape functions as load weights
// (exact total force, the moment of the force at the face's own point), node updates (eqs.
// 60-62).
#include "fsi/core/error.hpp"
#include "geometry_erp/interface_triangles.hpp"

#include <catch2/catch.hpp>

using namespace fsi;
using namespace fsi::erp;
using Catch::Matchers::WithinAbs;

namespace {

/// The top of a block [0, 1] x [0, 1] x [-1, 0] as two 6-node faces, fluid above (+z), its
/// mid-side nodes raised by `bulge` (a curved face).
InterfaceMesh3 lid(int order, double bulge) {
  InterfaceMesh3 m;
  m.order = order;
  m.X0 = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  if (order == 1) {
    m.faces = {{0, 1, 2, 0, 0, 0}, {0, 2, 3, 0, 0, 0}};
    return m;
  }
  // Mid-sides 4 (0-1), 5 (1-2), 6 (2-0), 7 (2-3), 8 (3-0).
  m.X0.insert(m.X0.end(), {{0.5, 0.0, bulge},
                           {1.0, 0.5, bulge},
                           {0.5, 0.5, 2.0 * bulge},
                           {0.5, 1.0, bulge},
                           {0.0, 0.5, bulge}});
  m.faces = {{0, 1, 2, 4, 5, 6}, {0, 2, 3, 6, 7, 8}};
  return m;
}

} // namespace

TEST_CASE("erp: interface triangles: NCR, fluid side, parent points, load weights",
          "[interface_walls][3d]") {
  for (const int order : {2, 1}) {
    INFO("order " << order);
    const InterfaceMesh3 mesh = lid(order, order == 2 ? 0.05 : 0.0);
    TriangleWallSet walls;
    const std::vector<Vec3> floor{{-1, -1, -2}, {2, -1, -2}, {2, 2, -2}};
    walls.add_triangles(floor, std::vector<std::array<int, 3>>{{0, 1, 2}}, 0); // before it
    const InterfaceTriangles it(walls, mesh, 5);
    CHECK(it.first_node() == 3);
    CHECK(it.node_count() == static_cast<int>(mesh.node_count()));
    CHECK(it.first_triangle() == 1);
    CHECK(it.triangle_count() == (order == 2 ? 8 : 2));
    for (int k = 0; k < it.node_count(); ++k) // NCR: interface node k is wall node first + k
      CHECK(walls.nodes().x[static_cast<std::size_t>(it.first_node() + k)] ==
            mesh.X0[static_cast<std::size_t>(k)]);
    double area = 0.0;
    for (int t = it.first_triangle(); t < it.first_triangle() + it.triangle_count(); ++t) {
      const auto tt = static_cast<std::size_t>(t);
      CHECK(walls.triangles().group[tt] == 5);
      CHECK(walls.face_normal(t).z() > 0.9); // the fluid's side: up, as the face's corners say
      const auto& [a, b, c] = walls.triangles().node[tt];
      const Vec3 xa = walls.nodes().x[static_cast<std::size_t>(a)];
      const Vec3 xb = walls.nodes().x[static_cast<std::size_t>(b)];
      const Vec3 xc = walls.nodes().x[static_cast<std::size_t>(c)];
      area += 0.5 * (xb - xa).cross(xc - xa).z();
      const auto f = static_cast<std::size_t>(it.face(t));
      for (const auto& [s, r] : {std::pair{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}, {0.2, 0.3}}) {
        // The wall point and the face's isoparametric point at its parent point: the same at
        // the flat triangle's vertices (they are face nodes), within the bulge between them.
        const Vec3 x_wall = xa + s * (xb - xa) + r * (xc - xa);
        const ParentPoint<3> p = it.parent_point(t, s, r);
        REQUIRE(in_parent_element(p));
        const Vec3 x_face = face_point(mesh, mesh.X0, f, p[0], p[1]);
        if (s + r == 0.0 || s == 1.0 || r == 1.0) CHECK((x_wall - x_face).norm() < 1e-15);
        CHECK((x_wall - x_face).head<2>().norm() < 1e-15); // the bulge is along z only
        // Load weights: a point force F shared by the face's nodes sums to F exactly and has
        // the moment of F placed at the face's point x(xi, eta) (eq. 58 in 3-D).
        const Vec3 F(0.3, -0.2, -1.0);
        const auto w = it.load_weights(t, s, r);
        Vec3 sum = Vec3::Zero(), moment = Vec3::Zero();
        for (std::size_t j = 0; j < 6; ++j) {
          CHECK(w.k[j] == mesh.faces[f][j]);
          sum += w.N[j] * F;
          moment += mesh.X0[w.k[j]].cross(w.N[j] * F);
        }
        CHECK((sum - F).norm() < 1e-15);
        CHECK((moment - x_face.cross(F)).norm() < 1e-15);
      }
    }
    CHECK_THAT(area, WithinAbs(1.0, 1e-14)); // the flat triangles cover the lid once
    // Eqs. 60-62: the wall nodes take the interface's state.
    NodeMotion3 state = NodeMotion3::zeros(mesh.node_count());
    for (std::size_t k = 0; k < state.size(); ++k) {
      state.x[k] = mesh.X0[k] + Vec3(0.0, 0.0, 0.1);
      state.v[k] = Vec3(1.0, 2.0, static_cast<double>(k));
      state.a[k] = Vec3(-1.0, 0.0, 0.5 * static_cast<double>(k));
    }
    it.update_nodes(walls, state.x, state.v, state.a);
    for (std::size_t k = 0; k < state.size(); ++k) {
      const auto L = static_cast<std::size_t>(it.first_node()) + k;
      CHECK(walls.nodes().x[L] == state.x[k]);
      CHECK(walls.nodes().v[L] == state.v[k]);
      CHECK(walls.nodes().a[L] == state.a[k]);
    }
  }
}

TEST_CASE("erp: interface triangles refuse a bad mesh and add nothing", "[interface_walls][3d]") {
  TriangleWallSet walls;
  InterfaceMesh3 bad = lid(2, 0.0);
  bad.faces[1][4] = 9;
  CHECK_THROWS_WITH(InterfaceTriangles(walls, bad, 0),
                    "interface: node 9 is not on the interface (9 nodes)");
  bad = lid(2, 0.0);
  bad.order = 3;
  CHECK_THROWS_WITH(InterfaceTriangles(walls, bad, 0),
                    "interface: faces of order 3 (1 or 2 expected)");
  bad = lid(1, 0.0);
  bad.faces[1] = {0, 2, 0, 0, 0, 0}; // a triangle with a repeated node
  CHECK_THROWS_AS(InterfaceTriangles(walls, bad, 0), InputError);
  CHECK(walls.triangles().size() == 0);
  CHECK(walls.nodes().size() == 0);
}
