// Moving triangle walls in 3-D (#43): a tank translating at a constant velocity U with water that
// starts at U is the static tank seen from a moving frame (Galilean invariance: the fluid terms
// and the wall terms read positions relative to the walls and velocities relative to v_wall):
// to round-off without the viscous loop; with it, up to the no-slip ghost of eq. 24 (of order
// nu U_n, not of dt), the viscous stage seeing the walls at t^n.
#include "fluid_emps/emps_fluid.hpp"
#include "fsi/core/state_archive.hpp"
#include "geometry_erp/box_walls.hpp"
#include "geometry_erp/motion3.hpp"
#include "test_support.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <vector>

using namespace fsi;

namespace {

/// s(t) = t: with direction U, the translation U t at velocity U.
class Uniform final : public erp::Motion {
public:
  erp::RigidKinematics at(double t) const override {
    erp::RigidKinematics k;
    k.d = Vec2(t, 0.0);
    k.d_dot = Vec2(1.0, 0.0);
    return k;
  }
};

emps::FluidOptions3 tank_water(double l0) { // the 3-D hydrostatic tank's recipe, undamped
  emps::FluidOptions3 o = emps::test::water<3>(l0, -0.2, 0.6);
  emps::apply_wall_preset(o, emps::WallModel::standard);
  o.viscosity = 1e-6;
  o.sound_speed = 15.0;
  o.wall.contact.alpha_rep = 1e5;
  o.gravity = Vec3(0, 0, -9.81);
  return o;
}

/// The largest differences, after time `t_end` in steps of dt, between the water in a tank
/// translating at U (starting at U) and in the same tank at rest, in the moving tank's frame.
struct Frames {
  double dx = 0, dv = 0, dp = 0; ///< m, m/s, Pa
  double p_max = 0, v_max = 0;   ///< the static run's largest |p|, |v| (not trivial)
  double min_gap = 1e300;        ///< a particle centre to the moving tank's faces, m
  std::size_t removed = 0;
};

Frames frames(const emps::FluidOptions3& o, const Vec3& U, double dt, double t_end) {
  const double l0 = o.l0;
  const int n = 6;
  const Vec3 hi(n * l0, n * l0, 2 * n * l0);
  erp::TriangleWallSet fixed, moving;
  erp::add_box_tank(fixed, Vec3::Zero(), hi, false, 0);
  erp::add_box_tank(moving, Vec3::Zero(), hi, false, 0);
  const erp::RigidTriangles3 motion{erp::RigidMotion3::translation(std::make_shared<Uniform>(), U),
                                    0, moving.nodes().x};
  motion.move(moving, 0.0);
  emps::EmpsFluid3 still(o, emps::test::block(n, n, n, l0), fixed);
  emps::EmpsFluid3 carried(o, emps::test::block(n, n, n, l0), moving);
  carried.set_velocities(std::vector<Vec3>(still.particles().size(), U));
  const auto &a = still.particles(), &b = carried.particles();
  Frames f;
  const long steps = std::lround(t_end / dt);
  for (long s = 0; s < steps; ++s) {
    motion.move(moving, static_cast<double>(s + 1) * dt); // the walls at t + dt, then the step
    still.advance(static_cast<double>(s) * dt, dt);
    carried.advance(static_cast<double>(s) * dt, dt);
    const Vec3 d = U * (static_cast<double>(s + 1) * dt);
    for (std::size_t i = 0; i < b.size(); ++i)
      for (int c = 0; c < 3; ++c)
        f.min_gap =
            std::min({f.min_gap, b.position[c][i] - d[c], hi[c] - (b.position[c][i] - d[c])});
  }
  f.removed = carried.removed();
  std::vector<std::size_t> of_id(a.size()); // the fluids sort by cell: pair particles by id
  for (std::size_t i = 0; i < b.size(); ++i) of_id[b.id[i]] = i;
  const Vec3 d = U * (static_cast<double>(steps) * dt);
  for (std::size_t i = 0; i < a.size(); ++i) {
    const std::size_t j = of_id[a.id[i]];
    for (int c = 0; c < 3; ++c) {
      f.dx = std::max(f.dx, std::abs(b.position[c][j] - d[c] - a.position[c][i]));
      f.dv = std::max(f.dv, std::abs(b.velocity[c][j] - U[c] - a.velocity[c][i]));
      f.v_max = std::max(f.v_max, std::abs(a.velocity[c][i]));
    }
    f.dp = std::max(f.dp, std::abs(b.p[j] - a.p[i]));
    f.p_max = std::max(f.p_max, std::abs(a.p[i]));
  }
  return f;
}

} // namespace

TEST_CASE("emps 3-D moving walls: without the viscous loop a tank and its water translating at "
          "U are the static tank in a moving frame to round-off",
          "[emps][walls3d]") {
  emps::FluidOptions3 o = tank_water(0.02);
  o.viscosity = 0.0, o.artificial_viscosity = 0.0, o.wall.mirror.approach_viscosity = 0.0;
  REQUIRE(!o.viscous_loop());
  const double rho_g_H = o.density * 9.81 * 0.12;              // 6 l0 of water
  const Frames f = frames(o, Vec3(0.3, -0.2, 0.1), 5e-4, 0.1); // 200 steps
  INFO("|x - U t - x_static| <= " << f.dx / o.l0 << " l0, |v - U - v_static| <= " << f.dv
                                  << " m/s, |p - p_static| <= " << f.dp / rho_g_H
                                  << " rho g H, nearest centre to a wall " << f.min_gap / o.l0
                                  << " l0");
  CHECK(f.p_max > 0.5 * rho_g_H); // the column falls onto the floor and rings: not trivial
  CHECK(f.v_max > 0.1);
  CHECK(f.dx < 1e-10 * o.l0); // x + U t loses the last digits of x: round-off, measured 6e-13 l0
  CHECK(f.dv < 1e-10);
  CHECK(f.dp < 1e-10 * rho_g_H);
  CHECK(f.removed == 0);
  CHECK(f.min_gap > 0.0); // no particle through a moving wall
}

// With the viscous loop the viscous stage queries the walls at x^n as they were at t^n
// (SpaceWalls::before; the caller has moved its own to t + dt), so the moving frame's difference
// no longer falls with dt (it was first order in dt, 2.6e-3 l0 at dt = 5e-4 s, with the walls at
// t + dt). What remains grows with nu: the paper's no-slip ghost v_i' = 2 v_wall,t - v_i (eq. 24)
// drops the wall's normal velocity, which a tank moving across its faces has.
TEST_CASE("emps 3-D moving walls: with the viscous loop (nu, the slip mirror) a tank and its "
          "water translating at U are the static tank in a moving frame to round-off",
          "[emps][walls3d]") {
  emps::FluidOptions3 o = tank_water(0.02);
  o.wall.mirror.condition = emps::WallCondition::slip; // v_i' = R_ref v_i + 2 (n . v_wall) n
  o.artificial_viscosity = 0.0, o.wall.mirror.approach_viscosity = 0.0;
  REQUIRE(o.viscous_loop());
  const double rho_g_H = o.density * 9.81 * 0.12;
  const Frames f = frames(o, Vec3(0.3, -0.2, 0.1), 5e-4, 0.1);
  INFO("|x - U t - x_static| <= " << f.dx / o.l0 << " l0, |v - U - v_static| <= " << f.dv
                                  << " m/s, |p - p_static| <= " << f.dp / rho_g_H << " rho g H");
  CHECK(f.p_max > 0.5 * rho_g_H);
  CHECK(f.dx < 1e-10 * o.l0); // the viscous stage sees the walls at t^n, as the static run does
  CHECK(f.dv < 1e-10);
  CHECK(f.dp < 1e-10 * rho_g_H);
  CHECK(f.removed == 0);
}

TEST_CASE("emps 3-D moving walls: with the no-slip mirror of eq. 24 the moving frame's difference "
          "is of order nu U_n, not of dt",
          "[emps][walls3d]") {
  emps::FluidOptions3 o = tank_water(0.02);
  REQUIRE(o.wall.mirror.condition == emps::WallCondition::no_slip);
  const Vec3 U(0.3, -0.2, 0.1);
  const Frames coarse = frames(o, U, 5e-4, 0.1), fine = frames(o, U, 2.5e-4, 0.1);
  o.viscosity *= 2.0;
  const Frames doubled = frames(o, U, 5e-4, 0.1);
  INFO("|x - U t - x_static| <= " << coarse.dx / o.l0 << " l0 at dt = 5e-4 s, " << fine.dx / o.l0
                                  << " l0 at 2.5e-4 s, " << doubled.dx / o.l0
                                  << " l0 with twice nu");
  CHECK(coarse.dx < 1e-3 * o.l0);
  CHECK_THAT(coarse.dx / fine.dx, Catch::Matchers::WithinAbs(1.0, 0.1));    // not first order in dt
  CHECK_THAT(doubled.dx / coarse.dx, Catch::Matchers::WithinAbs(2.0, 0.2)); // linear in nu
  CHECK(coarse.removed + fine.removed + doubled.removed == 0);
}

namespace {

/// A tank translating at U with its water, the viscous loop on (the walls at t^n are the fluid's
/// state: save/restore and checkpoints carry them).
struct MovingTank {
  explicit MovingTank(const emps::FluidOptions3& o) {
    erp::add_box_tank(walls, Vec3::Zero(), Vec3(6 * o.l0, 6 * o.l0, 12 * o.l0), false, 0);
    motion = erp::RigidTriangles3{erp::RigidMotion3::translation(std::make_shared<Uniform>(), U), 0,
                                  walls.nodes().x};
    motion->move(walls, 0.0);
    fluid = std::make_unique<emps::EmpsFluid3>(o, emps::test::block(6, 6, 6, o.l0), walls);
    fluid->set_velocities(std::vector<Vec3>(fluid->particles().size(), U));
  }
  void step(long s) { // the walls at t + dt, then the step
    motion->move(walls, static_cast<double>(s + 1) * dt);
    fluid->advance(static_cast<double>(s) * dt, dt);
  }
  const Vec3 U{0.3, -0.2, 0.1};
  const double dt = 5e-4;
  erp::TriangleWallSet walls;
  std::optional<erp::RigidTriangles3> motion;
  std::unique_ptr<emps::EmpsFluid3> fluid;
};

/// True when the two fluids' positions, velocities and pressures are bitwise equal.
bool bitwise_equal(const emps::Particles3& a, const emps::Particles3& b) {
  if (a.size() != b.size()) return false;
  for (int c = 0; c < 3; ++c)
    if (a.position[c] != b.position[c] || a.velocity[c] != b.velocity[c]) return false;
  return a.p == b.p && a.id == b.id;
}

} // namespace

TEST_CASE("emps 3-D moving walls: save/restore and checkpoints keep the walls at t^n",
          "[emps][walls3d]") {
  const emps::FluidOptions3 o = tank_water(0.02);
  REQUIRE(o.viscous_loop());
  MovingTank whole(o);
  for (long s = 0; s < 20; ++s) whole.step(s);

  SECTION("a step redone after restore() is the step done once") {
    MovingTank redone(o);
    for (long s = 0; s < 10; ++s) redone.step(s);
    const emps::EmpsFluid3::State saved = redone.fluid->save();
    redone.step(12); // an abandoned iterate: the walls two steps ahead
    redone.motion->move(redone.walls, 10 * redone.dt);
    redone.fluid->restore(saved);
    for (long s = 10; s < 20; ++s) redone.step(s);
    CHECK(bitwise_equal(redone.fluid->particles(), whole.fluid->particles()));
  }
  SECTION("a run continued from a checkpoint is the run not interrupted") {
    MovingTank first(o);
    for (long s = 0; s < 10; ++s) first.step(s);
    StateArchive archive;
    first.fluid->write_state(archive, "fluid/");
    CHECK(archive.reals("fluid/walls_before/x").size() == 3 * first.walls.nodes().x.size());
    MovingTank second(o); // its walls at t = 0 until the next step moves them
    second.fluid->read_state(archive, "fluid/");
    for (long s = 10; s < 20; ++s) second.step(s);
    CHECK(bitwise_equal(second.fluid->particles(), whole.fluid->particles()));
  }
}
