// Polygon walls from quadratic FE interface edges: NCR (eqs. 50-51), parent coordinates, shape
// functions, node updates (eqs. 60-62).
#include "fsi/core/error.hpp"
#include "geometry_erp/fe_interface.hpp"

#include <catch2/catch.hpp>

#include <random>

using namespace fsi;
using namespace fsi::erp;
using Catch::Matchers::WithinAbs;

namespace {

/// Nodes of a solid block [0, 1] x [0, 2] meshed with T6 elements (numbering scrambled; nodes 0,
/// 5 and 9 are interior), and its right, top and left sides as interface edges, counter-clockwise
/// around the solid.
struct Block {
  std::vector<Vec2> X0{{0.5, 1.0}, {1.0, 0.0}, {1.0, 1.0}, {1.0, 2.0}, {0.5, 2.0},
                       {0.5, 0.5}, {0.0, 2.0}, {0.0, 1.0}, {0.0, 0.0}, {0.5, 1.5}};
  std::vector<std::array<int, 3>> edges{{1, 2, 3}, {3, 4, 6}, {6, 7, 8}};
};

} // namespace

TEST_CASE("erp: edge shape functions: partition of unity, nodal values, 1/6 2/3 1/6 split",
          "[fe_interface]") {
  for (const double xi : {-1.0, -0.4, 0.0, 0.3, 1.0}) {
    const auto N = edge_shape_functions(xi);
    CHECK_THAT(N[0] + N[1] + N[2], WithinAbs(1.0, 1e-15));
  }
  const double nodes[3] = {-1.0, 0.0, 1.0};
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      CHECK(edge_shape_functions(nodes[a])[static_cast<std::size_t>(b)] == (a == b ? 1.0 : 0.0));
  // Uniform load: integral of N over the edge / length (3-point Gauss, exact for quadratics).
  const double g = std::sqrt(0.6), weight[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0},
               xi[3] = {-g, 0.0, g};
  std::array<double, 3> share{};
  for (int q = 0; q < 3; ++q)
    for (int k = 0; k < 3; ++k)
      share[static_cast<std::size_t>(k)] +=
          0.5 * weight[q] * edge_shape_functions(xi[q])[static_cast<std::size_t>(k)];
  CHECK_THAT(share[0], WithinAbs(1.0 / 6.0, 1e-15));
  CHECK_THAT(share[1], WithinAbs(2.0 / 3.0, 1e-15));
  CHECK_THAT(share[2], WithinAbs(1.0 / 6.0, 1e-15));
}

TEST_CASE("erp: FE interface: NCR round trip, positions, fluid side, parent coordinates",
          "[fe_interface]") {
  const Block block;
  WallSet walls;
  walls.add_polyline(std::vector<Vec2>{{-1.0, 0.0}, {3.0, 0.0}}, false, 0); // a floor before it
  const FeInterface fe(walls, block.X0, block.edges, 5);
  CHECK(fe.first_node() == 2);
  CHECK(fe.node_count() == 7);
  CHECK(fe.segment_count() == 6);
  for (int L = fe.first_node(); L < fe.first_node() + fe.node_count(); ++L) {
    REQUIRE(fe.polygon_node(fe.fe_node(L)) == L); // L -> K -> L
    CHECK(walls.nodes().x[static_cast<std::size_t>(L)] ==
          block.X0[static_cast<std::size_t>(fe.fe_node(L))]);
  }
  for (int K : {0, 5, 9}) CHECK(fe.polygon_node(K) == -1);
  for (int K : {1, 2, 3, 4, 6, 7, 8}) CHECK(fe.fe_node(fe.polygon_node(K)) == K); // K -> L -> K

  for (int s = fe.first_segment(); s < fe.first_segment() + fe.segment_count(); ++s) {
    CHECK(walls.segments().group[static_cast<std::size_t>(s)] == 5);
    // Fluid normal points away from the block's centre.
    const auto [a, b] = walls.segments().node[static_cast<std::size_t>(s)];
    const Vec2 mid = 0.5 * (walls.nodes().x[static_cast<std::size_t>(a)] +
                            walls.nodes().x[static_cast<std::size_t>(b)]);
    CHECK(walls.segment_normal(s).dot(mid - Vec2(0.5, 1.0)) > 0.0);
    // The point at t on the segment is the isoparametric edge point at xi(t) (straight edges).
    const auto& K = fe.edge_nodes(fe.edge(s));
    for (const double t : {0.0, 0.25, 0.5, 1.0}) {
      const double xi = fe.parent_coordinate(s, t);
      const auto N = edge_shape_functions(xi);
      const Vec2 x_fe = N[0] * block.X0[static_cast<std::size_t>(K[0])] +
                        N[1] * block.X0[static_cast<std::size_t>(K[1])] +
                        N[2] * block.X0[static_cast<std::size_t>(K[2])];
      const Vec2 x_seg = (1.0 - t) * walls.nodes().x[static_cast<std::size_t>(a)] +
                         t * walls.nodes().x[static_cast<std::size_t>(b)];
      CHECK((x_fe - x_seg).norm() < 1e-15);
    }
    // Point-load weights: sum 1 and first moment = the load point (force and moment kept).
    const auto [K_load, N_load] = fe.load_weights(s, 0.3);
    CHECK(K_load == K);
    CHECK_THAT(N_load[0] + N_load[1] + N_load[2], WithinAbs(1.0, 1e-15));
    const Vec2 moment_arm = N_load[0] * block.X0[static_cast<std::size_t>(K[0])] +
                            N_load[1] * block.X0[static_cast<std::size_t>(K[1])] +
                            N_load[2] * block.X0[static_cast<std::size_t>(K[2])];
    CHECK((moment_arm - (0.7 * walls.nodes().x[static_cast<std::size_t>(a)] +
                         0.3 * walls.nodes().x[static_cast<std::size_t>(b)]))
              .norm() < 1e-15);
    // Mid node <-> xi = 0.
    const int mid_end = fe.fe_node(a) == K[1] ? 0 : 1;
    CHECK(fe.half(s) == mid_end); // the half K1 -> Km ends at the mid node
    CHECK(fe.parent_coordinate(s, mid_end) == 0.0);
    CHECK(std::abs(fe.parent_coordinate(s, 1 - mid_end)) == 1.0);
  }
}

TEST_CASE("erp: FE interface: nodes follow the FE displacement, velocity, acceleration",
          "[fe_interface]") {
  const Block block;
  WallSet walls;
  const FeInterface fe(walls, block.X0, block.edges, 0);
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> r(-1.0, 1.0);
  std::vector<double> u(2 * block.X0.size()), v(u.size()), a(u.size());
  for (std::size_t k = 0; k < u.size(); ++k) u[k] = 0.01 * r(rng), v[k] = r(rng), a[k] = r(rng);
  fe.update_nodes(walls, block.X0, u, v, a);
  for (int L = 0; L < fe.node_count(); ++L) {
    const auto K = static_cast<std::size_t>(fe.fe_node(L));
    const auto l = static_cast<std::size_t>(L);
    CHECK(walls.nodes().x[l] == block.X0[K] + Vec2(u[2 * K], u[2 * K + 1]));
    CHECK(walls.nodes().v[l] == Vec2(v[2 * K], v[2 * K + 1]));
    CHECK(walls.nodes().a[l] == Vec2(a[2 * K], a[2 * K + 1]));
  }
}

TEST_CASE("erp: FE interface: a node index outside the mesh is an input error", "[fe_interface]") {
  const Block block;
  WallSet walls;
  const std::vector<std::array<int, 3>> bad{{1, 2, 30}};
  CHECK_THROWS_AS(FeInterface(walls, block.X0, bad, 0), InputError);
}
