// The SPH fluid's 3-D moving boundary from an interface mesh (fluid_sph/interface_boundary3.hpp):
// the boundary points behind a plate and inside a closed cube, the shape functions' partition of
// unity, the exact reaction (the load on the interface is minus the force of its points on the
// fluid), the load's sign and, in the slow tier, a still water column on a fixed plate carrying
// rho g H A (docs/fluid_sph.md, "3-D").
#include "fluid_sph/interface_boundary3.hpp"

#include <catch2/catch.hpp>

#include <Eigen/Geometry>
#include <cmath>
#include <random>

using namespace fsi;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

/// The square [0, W]^2 at z = 0 in n x n cells of two order-1 triangles, the solid below (corners
/// counter-clockwise seen from +z).
InterfaceMesh3 plate(double W, int n) {
  InterfaceMesh3 m;
  m.order = 1;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.X0.emplace_back(W * i / n, W * j / n, 0.0);
  const auto id = [n](int i, int j) { return static_cast<std::size_t>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      m.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j), id(i, j), id(i, j)});
      m.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1), id(i, j), id(i, j), id(i, j)});
    }
  return m;
}

/// The cube [0, L]^3 as 12 order-1 triangles, oriented outwards.
InterfaceMesh3 cube(double L) {
  InterfaceMesh3 m;
  m.order = 1;
  for (int k = 0; k < 8; ++k) m.X0.emplace_back(L * (k & 1), L * ((k >> 1) & 1), L * (k >> 2));
  const std::size_t q[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                               {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& f : q) {
    m.faces.push_back({f[0], f[1], f[2], f[0], f[0], f[0]});
    m.faces.push_back({f[0], f[2], f[3], f[0], f[0], f[0]});
  }
  return m;
}

/// A fluid periodic in x and y over [0, W)^2 standing on `points` at z < 0, gravity -z.
sph::SphOptions3 column_options(double dp, double W, double H) {
  const double g = 9.81;
  sph::SphOptions3 o;
  o.rho0 = 1000.0, o.dp = dp, o.c0 = 10.0 * std::sqrt(2.0 * g * H);
  o.u_ref = std::sqrt(2.0 * g * H), o.gravity = {0.0, 0.0, -g}, o.viscosity = 1e-6;
  o.wkgc_alpha = 0.3, o.fixed_dt = 0.5 * 0.6 * o.h() / o.c0, o.riemann_limiter = false;
  o.periodic_x = o.periodic_y = true;
  o.domain_min = Vec3(0.0, 0.0, -0.1), o.domain_max = Vec3(W, W, H + 0.2);
  return o;
}

} // namespace

TEST_CASE("sph 3-D interface: 4 layers behind a plate, none beyond its rim; a cube's inside",
          "[sph][3d][interface]") {
  const double dp = 0.01, W = 0.08;
  const sph::InterfaceBoundary3 b(plate(W, 5), dp, 4);
  const auto points = b.wall_points(0);
  CHECK(points.size() == 8 * 8 * 4);
  double err = 0.0;
  for (const auto& p : points) {
    err = std::max(err, (p.n - Vec3::UnitZ()).norm() + std::abs(p.depth + p.x.z()));
    CHECK(p.x.z() < 0.0);
    CHECK(p.x.x() > 0.0);
    CHECK(p.x.x() < W);
    CHECK(p.vol == Approx(dp * dp * dp));
  }
  CHECK(err < 1e-14);
  // A closed cube 10 dp wide: every lattice point inside but the 2^3 more than 4 dp deep.
  const double L = 10 * dp;
  const sph::InterfaceBoundary3 c(cube(L), dp, 4);
  CHECK(c.size() == 1000 - 8);
  const auto inside = c.wall_points(1);
  for (const auto& p : inside) {
    CHECK((p.x.array() > 0.0).all());
    CHECK((p.x.array() < L).all());
  }
  const InterfaceMesh3 m = cube(L);
  CHECK_THAT(c.signed_distance(m.X0, Vec3::Constant(0.5 * L)), WithinAbs(-0.5 * L, 1e-15));
  CHECK_THAT(c.signed_distance(m.X0, Vec3(0.5 * L, 0.5 * L, L + 0.003)), WithinAbs(0.003, 1e-15));
  CHECK_THAT(c.signed_distance(m.X0, Vec3(L + 0.003, L + 0.004, 0.5 * L)), WithinAbs(0.005, 1e-15));
  CHECK_THAT(c.signed_distance(m.X0, Vec3(L - 0.003, L - 0.004, 0.5 * L)),
             WithinAbs(-0.003, 1e-15));
}

TEST_CASE("sph 3-D interface: the points move with the faces, their forces sum to the nodes",
          "[sph][3d][interface]") {
  const double dp = 0.01;
  const InterfaceMesh3 m = cube(10 * dp);
  const sph::InterfaceBoundary3 b(m, dp, 4);
  // An affine motion x = A X + d: the shape functions reproduce it at every anchor, the points
  // keep their offsets in the faces' turned frames (exact for a rotation).
  const double t = 0.3;
  const Mat3 R = Eigen::AngleAxisd(t, Vec3(1.0, 2.0, 2.0) / 3.0).toRotationMatrix();
  const Vec3 d(0.2, -0.1, 0.05);
  std::vector<Vec3> x, x0, n0, xr, nr, anchor0, anchor;
  for (const Vec3& X : m.X0) x.push_back(R * X + d);
  b.place(m.X0, x0, n0);
  b.place(x, xr, nr);
  double err = 0.0;
  for (std::size_t p = 0; p < b.size(); ++p)
    err = std::max(err, (xr[p] - (R * x0[p] + d)).norm() + (nr[p] - R * n0[p]).norm());
  b.interpolate(m.X0, anchor0); // the anchors x(xi, eta), at X0 and moved
  b.interpolate(x, anchor);
  for (std::size_t p = 0; p < b.size(); ++p)
    err = std::max(err, (anchor[p] - (R * anchor0[p] + d)).norm());
  CHECK(err < 1e-14);
  // Partition of unity: random point forces reach the nodes whole.
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> f(b.size()), nodal;
  Vec3 total = Vec3::Zero();
  for (auto& q : f) q = Vec3(u(rng), u(rng), u(rng)), total += q;
  b.distribute(f, nodal);
  Vec3 sum = Vec3::Zero();
  for (const auto& q : nodal) sum += q;
  CHECK((sum - total).norm() < 1e-12);
}

TEST_CASE("sph 3-D interface: the load on a plate is minus its points' force on the fluid, and "
          "pushes harder when the plate accelerates into the fluid",
          "[sph][3d][interface][sign]") {
  const double dp = 0.02, W = 8 * dp, H = 6 * dp;
  const auto o = column_options(dp, W, H);
  const InterfaceMesh3 mesh = plate(W, 4);
  const sph::InterfaceBoundary3 b(mesh, dp, 4);
  const auto points = b.wall_points(0);
  // Momentum: the fluid's change is M g t minus the impulse handed to the plate's points, whose
  // nodal loads sum to it.
  sph::SphFluid3 f(o, sph::fill_box(Vec3::Zero(), Vec3(W, W, H), dp), points);
  f.track_wall_forces(0);
  const Vec3 P0 = f.momentum();
  const double M = o.mass() * static_cast<double>(f.particles().size());
  Vec3 impulse = Vec3::Zero();
  std::vector<Vec3> force(b.size()), nodal;
  for (int s = 0; s < 100; ++s) {
    const double dt = f.next_dt();
    f.advance(dt);
    for (std::size_t a = 0; a < b.size(); ++a) force[a] = f.wall_force(a), impulse += force[a] * dt;
  }
  b.distribute(force, nodal);
  Vec3 load = Vec3::Zero(), points_force = Vec3::Zero();
  for (const auto& q : nodal) load += q;
  for (const auto& q : force) points_force += q;
  const Vec3 gravity = M * o.gravity * f.time();
  const double residual = (f.momentum() - P0 - gravity + impulse).norm() / gravity.norm();
  const double nodes = (load - points_force).norm() / points_force.norm();
  INFO("t = " << f.time() << " s, impulse on the plate " << impulse.z()
              << " N s; momentum residual " << residual << " of M g t, nodal loads against the "
              << "points' force " << nodes);
  CHECK(residual < 1e-12);
  CHECK(nodes < 1e-12);
  CHECK(load.z() < 0.0); // the water pushes the plate down, out of the fluid
  // Eq. 16's a_w: the load rises linearly with the plate's acceleration towards the fluid.
  const auto push = [&](double a_w) {
    sph::SphFluid3 g(o, sph::fill_box(Vec3::Zero(), Vec3(W, W, H), dp), points);
    g.track_wall_forces(0);
    for (std::size_t a = 0; a < g.walls().size(); ++a) g.moved_walls().a[2][a] = a_w;
    g.advance(g.next_dt());
    double down = 0.0;
    for (std::size_t a = 0; a < g.walls().size(); ++a) down -= g.wall_force(a).z();
    return down;
  };
  const double still = push(0.0), up = push(4.0), down = push(-4.0);
  INFO("push on the plate: a_w = -4 " << down << ", 0 " << still << ", +4 " << up << " N");
  CHECK(up > still);
  CHECK(down < still);
  CHECK_THAT(up - still, WithinRel(still - down, 1e-9));
}

TEST_CASE("sph 3-D interface: a still water column on a fixed plate loads it with rho g H A",
          "[sph][3d][interface][hydrostatic][slow]") {
  // A W x W x H column at dp = H / 12, periodic in x and y, released at p = 0 on a plate of
  // boundary points (the only wall), the full Riemann dissipation, no damping. At rest the plate
  // carries the whole weight, M g = rho0 g H A (M = N rho0 dp^3 exactly); the load is the points'
  // tracked force distributed to the nodes, averaged over the last quarter of the run.
  const double dp = 0.02, W = 8 * dp, H = 12 * dp, t_end = 1.0;
  const auto o = column_options(dp, W, H);
  const InterfaceMesh3 mesh = plate(W, 4);
  const sph::InterfaceBoundary3 b(mesh, dp, 4);
  sph::SphFluid3 f(o, sph::fill_box(Vec3::Zero(), Vec3(W, W, H), dp), b.wall_points(0),
                   {[&](const Vec3& q) { return b.signed_distance(mesh.X0, q); }});
  f.track_wall_forces(0);
  std::vector<Vec3> force(b.size()), nodal;
  double load = 0.0, early = 0.0, late = 0.0;
  while (f.time() < t_end - 1e-12) {
    const double dt = f.next_dt();
    f.advance(dt);
    for (std::size_t a = 0; a < b.size(); ++a) force[a] = f.wall_force(a);
    b.distribute(force, nodal);
    double z = 0.0;
    for (const auto& q : nodal) z += q.z();
    if (f.time() < 0.25 * t_end) {
      early += f.kinetic_energy() * dt;
    } else if (f.time() > 0.75 * t_end) {
      late += f.kinetic_energy() * dt;
      load -= z * dt / (0.25 * t_end);
    }
  }
  const double expected = o.rho0 * 9.81 * H * W * W;
  INFO("mean load over the last quarter " << load << " N, rho g H A " << expected
                                          << " N; KE integral first quarter " << early << ", last "
                                          << late << "; " << f.steps() << " steps");
  CHECK(f.removed() == 0);
  CHECK(std::abs(load / expected - 1.0) < 0.01);
  CHECK(late < 1e-2 * early);
}

TEST_CASE("sph 3-D interface: the signed distance through the grid of faces equals the scan over "
          "all faces bit for bit",
          "[sph][3d][interface][grid][long]") {
  // A bumpy plate of 3,200 order-1 faces (nodes jittered up and down) and the same faces as
  // order 2 (mid-side nodes lifted): random points above, below, beyond the rim and far off, and
  // points just off nodes and edge midpoints, where equally near faces tie.
  const double dp = 0.005, W = 0.2;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0), bump(-0.002, 0.002);
  InterfaceMesh3 m = plate(W, 40);
  for (auto& X : m.X0) X.z() += bump(rng);
  InterfaceMesh3 m2 = m; // order 2: the mid-side nodes appended
  m2.order = 2;
  for (auto& k : m2.faces)
    for (std::size_t j = 0; j < 3; ++j) {
      m2.X0.push_back(0.5 * (m2.X0[k[j]] + m2.X0[k[(j + 1) % 3]]) + Vec3(0.0, 0.0, bump(rng)));
      k[3 + j] = m2.X0.size() - 1;
    }
  for (const InterfaceMesh3* mesh : {&m, &m2}) {
    const sph::InterfaceBoundary3 b(*mesh, dp, 4);
    std::vector<Vec3> q;
    for (int s = 0; s < 2000; ++s) {
      const double depth = s < 1000 ? 0.03 : 1.0; // near the plate, then far off
      q.emplace_back(1.4 * W * u(rng) - 0.2 * W, 1.4 * W * u(rng) - 0.2 * W,
                     depth * (2.0 * u(rng) - 1.0));
    }
    for (std::size_t k = 0; k < mesh->faces.size(); k += 7) {
      const auto& f = mesh->faces[k];
      q.push_back(m.X0[f[0]] + Vec3(0.0, 0.0, 1e-3));
      q.push_back(0.5 * (m.X0[f[0]] + m.X0[f[1]]) - Vec3(0.0, 0.0, 2e-3));
    }
    std::size_t differ = 0, inside = 0;
    for (const Vec3& p : q) {
      const double brute = b.signed_distance(mesh->X0, p);
      differ += b.signed_distance(p) == brute ? 0 : 1;
      inside += brute < 0.0 ? 1 : 0;
    }
    INFO(q.size() << " points, " << inside << " behind the plate");
    CHECK(differ == 0);
    CHECK(inside > q.size() / 4);
  }
}
