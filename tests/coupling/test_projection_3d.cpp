// The 3-D interface (triangular faces, core/include/fsi/core/interface_mesh.hpp) and the force
// projection onto it (eqs. 53-59): face shape functions, conservation of force and moment on a
// curved quadratic sphere patch and on flat linear triangles, chunking and thread count.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <random>
#include <span>
#include <vector>

#include <Eigen/Geometry>

#include "coupling/projection.hpp"
#include "fsi/core/parallel.hpp"

using fsi::Vec3;
using namespace fsi::coupling;

namespace {

/// Parent coordinates of the six face nodes (corners, then mid-sides 0-1, 1-2, 2-0).
constexpr std::array<std::array<double, 2>, 6> face_node_parent{
    {{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}, {0.5, 0.0}, {0.5, 0.5}, {0.0, 0.5}}};

/// A uniformly random point (xi, eta) of the parent triangle.
std::array<double, 2> random_parent(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double xi = u(rng);
  return {xi, u(rng) * (1.0 - xi)};
}

/// A patch of the sphere of radius 1.3 about c, longitude u in [0, 0.9], latitude v in
/// [-0.5, 0.4], on an n x n grid of cells, two triangles per cell. Every node, the mid-side ones
/// included, lies on the sphere (order 2: curved faces), or order 1: flat triangles on the corner
/// nodes. The corners run (u, v), (u + h, v), (u, v + h): (x1 - x0) x (x2 - x0) points away from
/// c, so the solid is the ball and the fluid outside (the face convention).
fsi::InterfaceMesh3 sphere_patch(int n, int order) {
  const Vec3 c(0.2, -0.1, 0.4);
  const double radius = 1.3, u0 = 0.0, du = 0.9, v0 = -0.5, dv = 0.9;
  const int per_cell = order == 2 ? 2 : 1; // grid steps per cell
  const int m = n * per_cell + 1;          // grid points per side
  fsi::InterfaceMesh3 mesh;
  mesh.order = order;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) {
      const double u = u0 + du * i / (m - 1), v = v0 + dv * j / (m - 1);
      mesh.X0.push_back(
          c + radius * Vec3(std::cos(v) * std::cos(u), std::cos(v) * std::sin(u), std::sin(v)));
    }
  const auto node = [m](int i, int j) { return static_cast<std::size_t>(j * m + i); };
  const int s = per_cell;
  for (int cj = 0; cj < n; ++cj)
    for (int ci = 0; ci < n; ++ci) {
      const int i = ci * s, j = cj * s;
      if (order == 2) {
        mesh.faces.push_back({node(i, j), node(i + 2, j), node(i, j + 2), node(i + 1, j),
                              node(i + 1, j + 1), node(i, j + 1)});
        mesh.faces.push_back({node(i + 2, j), node(i + 2, j + 2), node(i, j + 2),
                              node(i + 2, j + 1), node(i + 1, j + 2), node(i + 1, j + 1)});
      } else {
        const std::size_t a = node(i, j), b = node(i + 1, j), d = node(i, j + 1);
        const std::size_t e = node(i + 1, j + 1);
        mesh.faces.push_back({a, b, d, a, a, a});
        mesh.faces.push_back({b, e, d, b, b, b});
      }
    }
  return mesh;
}

/// Projects n_loads random point loads at isoparametric points x(xi, eta) and checks the nodal
/// forces' total force and moment about a random pivot against the loads' own.
void check_patch_conservation(int order, std::size_t n_loads, unsigned seed) {
  std::mt19937 rng(seed);
  const fsi::InterfaceMesh3 mesh = sphere_patch(4, order);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<std::size_t> pick(0, mesh.faces.size() - 1);
  const Vec3 pivot(3.0 * u(rng), 3.0 * u(rng), 3.0 * u(rng));
  std::vector<PointLoad3> loads;
  Vec3 force = Vec3::Zero(), moment = Vec3::Zero();
  double force_scale = 0.0, moment_scale = 0.0;
  for (std::size_t k = 0; k < n_loads; ++k) {
    const auto s = k < 6 ? face_node_parent[k] : random_parent(rng); // the nodes, then anywhere
    const PointLoad3 p{pick(rng), s[0], s[1], Vec3(u(rng), u(rng), u(rng))};
    const Vec3 r = fsi::face_point(mesh, mesh.X0, p.face, p.xi, p.eta) - pivot;
    force += p.f;
    moment += r.cross(p.f);
    force_scale += p.f.norm();
    moment_scale += r.norm() * p.f.norm();
    loads.push_back(p);
  }
  auto out = InterfaceLoads3::zeros(mesh.node_count());
  project_point_loads(mesh, loads, out);
  Vec3 force_nodal = Vec3::Zero(), moment_nodal = Vec3::Zero();
  for (std::size_t i = 0; i < mesh.node_count(); ++i) {
    force_nodal += out.f[i];
    moment_nodal += (mesh.X0[i] - pivot).cross(out.f[i]);
  }
  const double force_error = (force_nodal - force).norm() / force_scale;
  const double moment_error = (moment_nodal - moment).norm() / moment_scale;
  CHECK(force_error <= 1e-12);
  CHECK(moment_error <= 1e-12);
}

} // namespace

TEST_CASE("face shape functions: partition of unity, nodal values, exact fields",
          "[coupling][projection][3d]") {
  std::mt19937 rng(11u);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  // A linear and a quadratic field of (xi, eta) with random coefficients.
  std::array<double, 6> c{};
  for (double& ck : c) ck = u(rng);
  const auto linear = [&](double x, double y) { return c[0] + c[1] * x + c[2] * y; };
  const auto quadratic = [&](double x, double y) {
    return linear(x, y) + c[3] * x * x + c[4] * x * y + c[5] * y * y;
  };
  for (int trial = 0; trial < 200; ++trial) {
    const auto [xi, eta] = random_parent(rng);
    for (const int order : {1, 2}) {
      const auto n = fsi::face_shape_functions(order, xi, eta);
      double sum = 0.0, field = 0.0, field_quadratic = 0.0;
      for (std::size_t k = 0; k < 6; ++k) {
        const auto [xk, yk] = face_node_parent[k];
        sum += n[k];
        field += n[k] * linear(xk, yk);
        field_quadratic += n[k] * quadratic(xk, yk);
      }
      CHECK(std::abs(sum - 1.0) <= 1e-15);
      CHECK(std::abs(field - linear(xi, eta)) <= 1e-14);
      if (order == 2) CHECK(std::abs(field_quadratic - quadratic(xi, eta)) <= 1e-14);
      if (order == 1)
        CHECK(std::abs(n[3]) + std::abs(n[4]) + std::abs(n[5]) == 0.0); // no mid nodes
    }
  }
  // Kronecker property: N_k(node j) = delta_kj at the 6 nodes (order 2), the 3 corners (order 1).
  for (const int order : {1, 2})
    for (std::size_t j = 0; j < (order == 2 ? 6u : 3u); ++j) {
      const auto n =
          fsi::face_shape_functions(order, face_node_parent[j][0], face_node_parent[j][1]);
      for (std::size_t k = 0; k < 6; ++k) CHECK(n[k] == (k == j ? 1.0 : 0.0));
    }
}

TEST_CASE("face_point interpolates the nodes of a curved face", "[coupling][projection][3d]") {
  const fsi::InterfaceMesh3 mesh = sphere_patch(2, 2);
  for (std::size_t f = 0; f < mesh.faces.size(); ++f)
    for (std::size_t k = 0; k < 6; ++k) {
      const Vec3 x =
          fsi::face_point(mesh, mesh.X0, f, face_node_parent[k][0], face_node_parent[k][1]);
      CHECK((x - mesh.X0[mesh.faces[f][k]]).norm() == 0.0);
    }
  // Orientation: (x1 - x0) x (x2 - x0) points away from the sphere's centre, into the fluid.
  const auto& k = mesh.faces[0];
  const Vec3 normal = (mesh.X0[k[1]] - mesh.X0[k[0]]).cross(mesh.X0[k[2]] - mesh.X0[k[0]]);
  CHECK(normal.dot(mesh.X0[k[0]] - Vec3(0.2, -0.1, 0.4)) > 0.0);
}

TEST_CASE("3-D projection conserves total force and moment", "[coupling][projection][3d]") {
  // The load point is the isoparametric x(xi, eta): sum_k N_k = 1 makes the force exact and
  // sum_k N_k x_k = x(xi, eta) the moment sum_k x_k x f_k = x(xi, eta) x f.
  SECTION("curved quadratic faces, few loads (sequential path)") {
    check_patch_conservation(2, 300, 1u);
  }
  SECTION("curved quadratic faces, many loads (chunked parallel path)") {
    check_patch_conservation(2, 50000, 2u);
  }
  SECTION("flat linear faces (a TL-SPH surface)") {
    check_patch_conservation(1, 300, 3u);
  }
  SECTION("flat linear faces, many loads") {
    check_patch_conservation(1, 20000, 4u);
  }
}

TEST_CASE("3-D projection: chunked equals unchunked, whatever the thread count",
          "[coupling][projection][3d]") {
  const fsi::InterfaceMesh3 mesh = sphere_patch(3, 2);
  std::mt19937 rng(5u);
  std::uniform_int_distribution<int> eighth(0, 8), force(-1000, 1000);
  SECTION("exact arithmetic: every load counted once, in any chunking") {
    // Parent points on multiples of 1/8 and integer forces: every N_k f is exact, every sum of
    // them too (far below 2^53 / 64), so any order of summation gives the same bits.
    std::vector<PointLoad3> loads;
    for (std::size_t k = 0; k < 30000; ++k) {
      const int a = eighth(rng), b = std::uniform_int_distribution<int>(0, 8 - a)(rng);
      loads.push_back(
          {k % mesh.faces.size(), a / 8.0, b / 8.0, Vec3(force(rng), force(rng), force(rng))});
    }
    auto chunked = InterfaceLoads3::zeros(mesh.node_count());
    auto unchunked = InterfaceLoads3::zeros(mesh.node_count());
    project_point_loads(mesh, loads, chunked);                       // 8 chunks of 3750
    for (std::size_t begin = 0; begin < loads.size(); begin += 1000) // one chunk per call
      project_point_loads(mesh, std::span(loads).subspan(begin, 1000), unchunked);
    for (std::size_t i = 0; i < mesh.node_count(); ++i)
      CHECK((chunked.f[i] - unchunked.f[i]).norm() == 0.0);
  }
  SECTION("random loads: the threads do not change a bit") {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<PointLoad3> loads;
    for (std::size_t k = 0; k < 40000; ++k) {
      const auto [xi, eta] = random_parent(rng);
      loads.push_back({k % mesh.faces.size(), xi, eta, Vec3(u(rng), u(rng), u(rng))});
    }
    auto parallel = InterfaceLoads3::zeros(mesh.node_count());
    auto sequential = InterfaceLoads3::zeros(mesh.node_count());
    project_point_loads(mesh, loads, parallel);
    fsi::set_sequential(true);
    project_point_loads(mesh, loads, sequential);
    fsi::set_sequential(false);
    for (std::size_t i = 0; i < mesh.node_count(); ++i)
      CHECK((parallel.f[i] - sequential.f[i]).norm() == 0.0);
  }
}

TEST_CASE("3-D interface motion interpolates node by node", "[coupling][3d]") {
  auto a = InterfaceMotion3::zeros(2), b = InterfaceMotion3::zeros(2);
  a.x[1] = Vec3(1.0, 2.0, 3.0);
  b.x[1] = Vec3(3.0, -2.0, 5.0);
  b.v[0] = Vec3(0.0, 0.0, 4.0);
  b.a[1] = Vec3(-8.0, 0.0, 0.0);
  const auto m = interpolate(a, b, 0.25);
  CHECK((m.x[1] - Vec3(1.5, 1.0, 3.5)).norm() == 0.0);
  CHECK((m.v[0] - Vec3(0.0, 0.0, 1.0)).norm() == 0.0);
  CHECK((m.a[1] - Vec3(-2.0, 0.0, 0.0)).norm() == 0.0);
  CHECK((interpolate(a, b, 1.0).x[1] - b.x[1]).norm() == 0.0);
}
