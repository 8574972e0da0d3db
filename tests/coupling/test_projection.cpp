// Force projection (eqs. 53-59): conservation of force and moment, uniform traction split.
#include <catch2/catch.hpp>

#include <random>
#include <vector>

#include "coupling/projection.hpp"
#include "fsi/core/parallel.hpp"

using fsi::Vec2;
using namespace fsi::coupling;

namespace {

double cross(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// A chain of `n_edges` edges sharing corner nodes: order 2, curved (mid node off the chord);
// order 1, straight (the mid slot names the first node and carries no weight).
fsi::InterfaceMesh random_chain(std::mt19937& rng, std::size_t n_edges, int order = 2) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  fsi::InterfaceMesh c;
  c.order = order;
  Vec2 p(u(rng), u(rng));
  c.X0.push_back(p);
  for (std::size_t e = 0; e < n_edges; ++e) {
    const Vec2 q = p + Vec2(0.5 + 0.5 * std::abs(u(rng)), 0.5 * u(rng));
    const Vec2 chord = q - p;
    const Vec2 normal(-chord.y(), chord.x());
    const Vec2 mid = 0.5 * (p + q) + 0.3 * u(rng) * normal + 0.1 * u(rng) * chord;
    const std::size_t a = c.X0.size() - 1;
    if (order == 2) {
      c.X0.push_back(mid);
      c.X0.push_back(q);
      c.edges.push_back({a, a + 1, a + 2});
    } else {
      c.X0.push_back(q);
      c.edges.push_back({a, a, a + 1});
    }
    p = q;
  }
  return c;
}

void check_chain_conservation(std::size_t n_edges, std::size_t n_loads, unsigned seed,
                              int order = 2) {
  std::mt19937 rng(seed);
  const fsi::InterfaceMesh c = random_chain(rng, n_edges, order);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<std::size_t> pick(0, n_edges - 1);
  std::vector<PointLoad> loads;
  Vec2 total = Vec2::Zero();
  const Vec2 pivot(u(rng) * 3.0, u(rng) * 3.0);
  double moment = 0.0;
  for (std::size_t k = 0; k < n_loads; ++k) {
    PointLoad p{pick(rng), u(rng), Vec2(u(rng), u(rng))};
    if (k == 0) p.xi = -1.0;
    if (k == 1) p.xi = 1.0;
    const Vec2 x = fsi::edge_point(c, c.X0, p.edge, p.xi);
    total += p.f;
    moment += cross(x - pivot, p.f);
    loads.push_back(p);
  }
  InterfaceLoads out = InterfaceLoads::zeros(c.X0.size());
  project_point_loads(c, loads, out);
  Vec2 total_nodal = Vec2::Zero();
  double moment_nodal = 0.0;
  for (std::size_t i = 0; i < c.X0.size(); ++i) {
    total_nodal += out.f[i];
    moment_nodal += cross(c.X0[i] - pivot, out.f[i]);
  }
  const double scale = static_cast<double>(n_loads);
  CHECK((total_nodal - total).norm() <= 1e-12 * scale);
  CHECK(std::abs(moment_nodal - moment) <= 1e-12 * scale);
}

} // namespace

TEST_CASE("edge shape functions: partition of unity and nodal values", "[coupling][projection]") {
  for (const int order : {1, 2})
    for (double xi : {-1.0, -0.3, 0.0, 0.71, 1.0}) {
      const auto n = fsi::edge_shape_functions(order, xi);
      CHECK_THAT(n[0] + n[1] + n[2], Catch::WithinAbs(1.0, 1e-15));
      CHECK_THAT(-n[0] + n[2], Catch::WithinAbs(xi, 1e-15)); // reproduces x = xi on [-1, 0, 1]
    }
  CHECK(fsi::edge_shape_functions(2, -1.0)[0] == 1.0);
  CHECK(fsi::edge_shape_functions(2, 0.0)[1] == 1.0);
  CHECK(fsi::edge_shape_functions(2, 1.0)[2] == 1.0);
  CHECK(fsi::edge_shape_functions(1, 0.0)[1] == 0.0); // an order-1 edge has no mid node
  CHECK(fsi::edge_shape_functions(1, -1.0)[0] == 1.0);
  CHECK(fsi::edge_shape_functions(1, 1.0)[2] == 1.0);
}

TEST_CASE("projection conserves total force and moment on curved quadratic edges",
          "[coupling][projection]") {
  // The load point is the isoparametric x(xi), where moment conservation is exact.
  SECTION("few loads (sequential path)") {
    check_chain_conservation(7, 200, 1u);
  }
  SECTION("many loads (chunked parallel path)") {
    check_chain_conservation(13, 50000, 2u);
  }
  SECTION("straight order-1 edges (a TL-SPH surface)") {
    check_chain_conservation(11, 300, 4u, 1);
  }
}

TEST_CASE("projection is independent of the thread count", "[coupling][projection]") {
  std::mt19937 rng(3u);
  const fsi::InterfaceMesh c = random_chain(rng, 9);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<PointLoad> loads;
  for (int k = 0; k < 40000; ++k)
    loads.push_back({static_cast<std::size_t>(k % 9), u(rng), Vec2(u(rng), u(rng))});
  InterfaceLoads par = InterfaceLoads::zeros(c.X0.size());
  InterfaceLoads seq = InterfaceLoads::zeros(c.X0.size());
  project_point_loads(c, loads, par);
  fsi::set_sequential(true);
  project_point_loads(c, loads, seq);
  fsi::set_sequential(false);
  for (std::size_t i = 0; i < c.X0.size(); ++i) CHECK((par.f[i] - seq.f[i]).norm() == 0.0);
}

TEST_CASE("uniform traction on a straight edge splits 1/6, 2/3, 1/6", "[coupling][projection]") {
  // Straight edge of length L, mid node at the centre; traction q integrated with 5 Gauss points
  // (exact for the quadratic shape functions): f_k = q L/2 sum_g w_g N_k(xi_g).
  const double length = 0.37;
  const Vec2 q(2.5, -4.0);
  fsi::InterfaceMesh edge;
  edge.X0 = {Vec2(0.0, 0.0), Vec2(0.5 * length, 0.0), Vec2(length, 0.0)};
  edge.edges = {{0, 1, 2}};
  const double g1 = 0.5384693101056831, g2 = 0.9061798459386640;
  const double w0 = 0.5688888888888889, w1 = 0.4786286704993665, w2 = 0.2369268850561891;
  const std::vector<std::pair<double, double>> gauss{
      {0.0, w0}, {-g1, w1}, {g1, w1}, {-g2, w2}, {g2, w2}};
  std::vector<PointLoad> loads;
  for (const auto& [xi, w] : gauss) loads.push_back({0, xi, 0.5 * length * w * q});
  InterfaceLoads out = InterfaceLoads::zeros(3);
  project_point_loads(edge, loads, out);
  const Vec2 total = length * q;
  CHECK((out.f[0] - total / 6.0).norm() <= 1e-14);
  CHECK((out.f[1] - 2.0 * total / 3.0).norm() <= 1e-14);
  CHECK((out.f[2] - total / 6.0).norm() <= 1e-14);
}
