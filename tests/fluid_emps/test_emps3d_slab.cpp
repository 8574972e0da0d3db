// The quasi-2-D slab (#43): a 2-D EMPS case extruded along z between two slip side walls
// (wall_condition: slip, eq. 24 with the mirror velocity R_ref v_i). The side walls must be
// invisible to a flow along them: pnd uniform across z, no shear, and a settling column that
// moves as the 2-D one does.
#include "fluid_emps/emps_fluid.hpp"
#include "geometry_erp/box_walls.hpp"
#include "slab_support.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace fsi;
using namespace fsi::emps::test;

TEST_CASE("emps 3-D slab: between slip side walls a column has pnd = n0 below the surface "
          "layer, the same in every z layer, and settles within 1.5 times the 2-D column's "
          "largest speed",
          "[emps][walls3d]") {
  const int nx = 12, ny = 8; // a column 12 x 8 l0 in a tank 12 x 16 x 6 l0
  erp::TriangleWallSet tank;
  erp::add_box_tank(tank, Vec3::Zero(), l0 * Vec3(nx, 2 * ny, nz), false, 0);
  erp::WallSet walls;
  walls.add_polyline(
      std::vector<Vec2>{{0.0, 2 * ny * l0}, {0.0, 0.0}, {nx * l0, 0.0}, {nx * l0, 2 * ny * l0}},
      false, 0);
  const emps::FluidOptions3 o3 = slab_water();
  emps::EmpsFluid3 slab(o3, emps::test::block(nx, ny, nz, l0), tank);
  emps::EmpsFluid plane(plane_water(), block2(nx, ny), walls);
  const emps::Particles3& s = slab.particles();
  const emps::Particles& p = plane.particles();
  const std::size_t layer = static_cast<std::size_t>(nx * ny);
  REQUIRE(s.size() == layer * nz);

  // At rest: the side walls' z completes the support across z (eq. 20), so every particle more
  // than r_e below the free surface has pnd = n0, corners of three faces included; the surface
  // layer, which the side walls' virtual lattice also fills above the water, reads more there.
  const double H = ny * l0, r_e = o3.r_e();
  std::vector<double> pnd(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) pnd[s.id[i]] = s.pnd[i];
  double bulk = 0.0, spread = 0.0, surface = 0.0;
  for (std::size_t c = 0; c < layer; ++c) { // the lattice column (i, j) through every z layer
    const auto [lo, hi] = across_z(pnd, c, layer);
    const double y = l0 * (static_cast<double>(c / nx) + 0.5);
    if (y < H - r_e) {
      bulk = std::max({bulk, std::abs(hi / slab.n0() - 1), std::abs(lo / slab.n0() - 1)});
      spread = std::max(spread, (hi - lo) / slab.n0());
    } else {
      surface = std::max(surface, (hi - lo) / slab.n0());
    }
  }
  INFO("below the surface layer |pnd/n0 - 1| <= " << bulk << ", its spread across z " << spread
                                                  << "; in the surface layer the spread is "
                                                  << surface);
  CHECK(bulk < 1e-12);
  CHECK(spread < 1e-12);

  // 0.05 s undamped (500 steps at C = 0.2): the column settles from its lattice start. Not
  // particle by particle as the 2-D one (measured: |v_xy - v_2D| up to 0.048 m/s against the
  // 2-D column's largest |v|, 0.029 m/s): the surface layer beside the side walls reads more pnd.
  const double dt = 0.2 * l0 / 20.0;
  for (int step = 0; step < 500; ++step) {
    slab.advance(step * dt, dt);
    plane.advance(step * dt, dt);
  }
  std::vector<Vec2> v2(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) v2[p.id[i]] = Vec2(p.vx[i], p.vy[i]);
  double v_plane = 0.0, v_slab = 0.0, vz = 0.0, dv = 0.0;
  for (const Vec2& v : v2) v_plane = std::max(v_plane, v.norm());
  for (std::size_t i = 0; i < s.size(); ++i) {
    const Vec2 v(s.vx[i], s.vy[i]);
    v_slab = std::max(v_slab, std::hypot(v.norm(), s.velocity[2][i]));
    vz = std::max(vz, std::abs(s.velocity[2][i]));
    dv = std::max(dv, (v - v2[s.id[i] % layer]).norm());
  }
  INFO("after 0.05 s: largest |v| slab " << v_slab << " m/s, 2-D " << v_plane
                                         << " m/s; largest |v_z| " << vz
                                         << " m/s; largest |v_xy - v_2D| " << dv << " m/s");
  CHECK(slab.removed() == 0);
  CHECK(v_plane > 0.0);
  CHECK(v_slab <= 1.5 * v_plane);
  CHECK(vz <= 0.25 * v_slab);
}

TEST_CASE("emps 3-D slab: water flowing along slip side walls keeps its velocity to round-off; "
          "no-slip side walls slow the rows beside them",
          "[emps][walls3d]") {
  // A block filling a long tunnel's cross-section (y and z between walls), free at its ends,
  // moving at U along x without gravity: the lattice slides along the walls at pnd = n0, no pair
  // closes, so only the viscous mirror term (eq. 24) can act, and with the slip mirror it is zero.
  const int nx = 8, ny = 6;
  erp::TriangleWallSet tunnel;
  erp::add_box_tank(tunnel, Vec3(-8 * l0, 0, 0), l0 * Vec3(16, ny, nz), false, 0);
  const double U = 0.5, dt = 2.5e-5;
  for (const auto condition : {emps::WallCondition::slip, emps::WallCondition::no_slip}) {
    emps::FluidOptions3 o = slab_water();
    o.gravity = Vec3::Zero();
    o.viscosity = 1e-3; // a wall shear a no-slip wall shows in 40 steps
    o.wall.mirror.condition = condition;
    emps::EmpsFluid3 fluid(o, emps::test::block(nx, ny, nz, l0), tunnel);
    fluid.set_velocities(std::vector<Vec3>(fluid.particles().size(), Vec3(U, 0.0, 0.0)));
    for (int step = 0; step < 40; ++step) fluid.advance(step * dt, dt);
    const auto& s = fluid.particles();
    double dv = 0.0;
    for (std::size_t i = 0; i < s.size(); ++i)
      dv = std::max({dv, std::abs(s.vx[i] - U), std::abs(s.vy[i]), std::abs(s.velocity[2][i])});
    INFO((condition == emps::WallCondition::slip ? "slip" : "no-slip")
         << ": largest |v - U| " << dv << " m/s");
    if (condition == emps::WallCondition::slip)
      CHECK(dv < 1e-12 * U);
    else
      CHECK(dv > 1e-3 * U);
  }
}
