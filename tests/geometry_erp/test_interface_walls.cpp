// Polygon walls from a structure's interface mesh: NCR (eqs. 50-51), parent coordinates, shape
// functions, node updates (eqs. 60-62), for quadratic (FE) and straight (particle) edges.
#include "fsi/core/error.hpp"
#include "geometry_erp/interface_walls.hpp"

#include <catch2/catch.hpp>

#include <random>

using namespace fsi;
using namespace fsi::erp;
using Catch::Matchers::WithinAbs;

namespace {

/// The right, top and left sides of a solid block [0, 1] x [0, 2] as order-2 interface edges,
/// counter-clockwise around the solid (the solid on the left of a -> b).
InterfaceMesh block(int order) {
  InterfaceMesh m;
  m.order = order;
  if (order == 2) {
    m.X0 = {{1.0, 0.0}, {1.0, 1.0}, {1.0, 2.0}, {0.5, 2.0}, {0.0, 2.0}, {0.0, 1.0}, {0.0, 0.0}};
    m.edges = {{0, 1, 2}, {2, 3, 4}, {4, 5, 6}};
  } else {
    m.X0 = {{1.0, 0.0}, {1.0, 2.0}, {0.0, 2.0}, {0.0, 0.0}};
    m.edges = {{0, 0, 1}, {1, 1, 2}, {2, 2, 3}};
  }
  return m;
}

} // namespace

TEST_CASE("erp: edge shape functions: partition of unity, nodal values, 1/6 2/3 1/6 split",
          "[interface_walls]") {
  for (const double xi : {-1.0, -0.4, 0.0, 0.3, 1.0}) {
    const auto N = edge_shape_functions(2, xi);
    CHECK_THAT(N[0] + N[1] + N[2], WithinAbs(1.0, 1e-15));
  }
  const double nodes[3] = {-1.0, 0.0, 1.0};
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      CHECK(edge_shape_functions(2, nodes[a])[static_cast<std::size_t>(b)] == (a == b ? 1.0 : 0.0));
  // Uniform load: integral of N over the edge / length (3-point Gauss, exact for quadratics).
  const double g = std::sqrt(0.6), weight[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0},
               xi[3] = {-g, 0.0, g};
  std::array<double, 3> share{};
  for (int q = 0; q < 3; ++q)
    for (int k = 0; k < 3; ++k)
      share[static_cast<std::size_t>(k)] +=
          0.5 * weight[q] * edge_shape_functions(2, xi[q])[static_cast<std::size_t>(k)];
  CHECK_THAT(share[0], WithinAbs(1.0 / 6.0, 1e-15));
  CHECK_THAT(share[1], WithinAbs(2.0 / 3.0, 1e-15));
  CHECK_THAT(share[2], WithinAbs(1.0 / 6.0, 1e-15));
}

TEST_CASE("erp: interface walls: NCR, positions, fluid side, parent coordinates, load weights",
          "[interface_walls]") {
  for (const int order : {2, 1}) {
    INFO("order " << order);
    const InterfaceMesh mesh = block(order);
    WallSet walls;
    walls.add_polyline(std::vector<Vec2>{{-1.0, 0.0}, {3.0, 0.0}}, false, 0); // a floor before it
    const InterfaceWalls iw(walls, mesh, 5);
    CHECK(iw.first_node() == 2);
    CHECK(iw.node_count() == static_cast<int>(mesh.node_count()));
    CHECK(iw.segment_count() == static_cast<int>(order * mesh.edges.size()));
    for (int k = 0; k < iw.node_count(); ++k) // NCR: interface node k is polygon node first + k
      CHECK(walls.nodes().x[static_cast<std::size_t>(iw.first_node() + k)] ==
            mesh.X0[static_cast<std::size_t>(k)]);
    for (int s = iw.first_segment(); s < iw.first_segment() + iw.segment_count(); ++s) {
      CHECK(walls.segments().group[static_cast<std::size_t>(s)] == 5);
      // Fluid normal points away from the block's centre.
      const auto [a, b] = walls.segments().node[static_cast<std::size_t>(s)];
      const Vec2 xa = walls.nodes().x[static_cast<std::size_t>(a)];
      const Vec2 xb = walls.nodes().x[static_cast<std::size_t>(b)];
      CHECK(walls.segment_normal(s).dot(0.5 * (xa + xb) - Vec2(0.5, 1.0)) > 0.0);
      // The point at t on the segment is the isoparametric edge point at xi(t).
      const auto e = static_cast<std::size_t>(iw.edge(s));
      for (const double t : {0.0, 0.25, 0.5, 1.0}) {
        const Vec2 x_edge = edge_point(mesh, mesh.X0, e, iw.parent_coordinate(s, t));
        CHECK((x_edge - ((1.0 - t) * xa + t * xb)).norm() < 1e-15);
      }
      // Point-load weights: sum 1 and first moment = the load point (force and moment kept).
      const auto [k_load, N_load] = iw.load_weights(s, 0.3);
      CHECK(k_load == mesh.edges[e]);
      CHECK_THAT(N_load[0] + N_load[1] + N_load[2], WithinAbs(1.0, 1e-15));
      Vec2 arm = Vec2::Zero();
      for (int j = 0; j < 3; ++j) arm += N_load[static_cast<std::size_t>(j)] * mesh.X0[k_load[j]];
      CHECK((arm - (0.7 * xa + 0.3 * xb)).norm() < 1e-15);
    }
  }
}

TEST_CASE("erp: interface walls: nodes follow the structure's interface state",
          "[interface_walls]") {
  const InterfaceMesh mesh = block(2);
  WallSet walls;
  const InterfaceWalls iw(walls, mesh, 0);
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> r(-1.0, 1.0);
  std::vector<Vec2> x(mesh.node_count()), v(x.size()), a(x.size());
  for (std::size_t k = 0; k < x.size(); ++k)
    x[k] = mesh.X0[k] + 0.01 * Vec2(r(rng), r(rng)), v[k] = Vec2(r(rng), r(rng)),
    a[k] = Vec2(r(rng), r(rng));
  iw.update_nodes(walls, x, v, a);
  for (std::size_t k = 0; k < x.size(); ++k) {
    CHECK(walls.nodes().x[k] == x[k]);
    CHECK(walls.nodes().v[k] == v[k]);
    CHECK(walls.nodes().a[k] == a[k]);
  }
}

TEST_CASE("erp: interface walls: a node index outside the interface is an input error",
          "[interface_walls]") {
  InterfaceMesh bad = block(2);
  bad.edges.push_back({1, 2, 30});
  WallSet walls;
  CHECK_THROWS_AS(InterfaceWalls(walls, bad, 0), InputError);
  InterfaceMesh cubic = block(2);
  cubic.order = 3;
  CHECK_THROWS_AS(InterfaceWalls(walls, cubic, 0), InputError);
}
