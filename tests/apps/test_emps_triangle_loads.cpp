// The 3-D EMPS fluid's wall forces as loads on a T10 structure's interface (eqs. 52-59 in 3-D,
// emps_plugin::project_triangle_forces over erp::InterfaceTriangles): water in a tank whose floor
// is the top face of a T10 plate (fem::interface_of, 6-node faces, four flat triangles each).
// The forces the fluid records are what the walls add to its momentum (round-off), the loads are
// minus their share on the interface (round-off) and push the plate out of the fluid, and the
// still column's load on the plate is its weight rho g h A less what the side walls carry.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "emps/triangle_loads.hpp"
#include "geometry_erp/box_walls.hpp"
#include "structure_fem/box_mesher.hpp"
#include "structure_fem/interface_mesh.hpp"

using fsi::Vec3;
namespace emps = fsi::emps;
namespace erp = fsi::erp;

namespace {

/// A tank [0, L]^2 x [0, 2 h] of triangles, open at the top, whose floor is the top face (z = 0)
/// of a T10 plate of n x n cells: side walls from erp::add_box_tank, floor from InterfaceTriangles.
struct PlateTank {
  PlateTank(double L, double h, int n)
      : fe(fsi::fem::interface_of(
            fsi::fem::make_box_mesh({{0.0, 0.0, -0.1 * L}, {L, L, 0.1 * L}, {n, n, 1}}),
            {"z_max"})) {
    erp::TriangleWallSet box;
    erp::add_box_tank(box, Vec3::Zero(), Vec3(L, L, 2 * h), true, 0);
    box.update();
    std::vector<std::array<int, 3>> sides;
    for (std::size_t t = 0; t < box.triangles().node.size(); ++t)
      if (box.face_normal(static_cast<int>(t)).z() < 0.5) sides.push_back(box.triangles().node[t]);
    walls.add_triangles(box.nodes().x, sides, 0);
    plate.emplace(walls, fe.mesh, 1);
    walls.update();
  }
  fsi::fem::FeInterface3 fe;
  erp::TriangleWallSet walls;
  std::optional<erp::InterfaceTriangles> plate;
};

/// Water at l0 with gravity -g z in the domain box [-0.05, hi]^3.
emps::FluidOptions3 water(double l0, double hi) {
  emps::FluidOptions3 o;
  o.density = 1000.0;
  o.l0 = l0;
  o.sound_speed = 15.0;
  o.gravity = Vec3(0.0, 0.0, -9.81);
  o.domain_min = Vec3::Constant(-0.05);
  o.domain_max = Vec3::Constant(hi);
  return o;
}

std::vector<Vec3> square_column_lattice(int nx, int nz, double l0) {
  std::vector<Vec3> x;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < nx; ++j)
      for (int i = 0; i < nx; ++i) x.push_back(l0 * Vec3(i + 0.5, j + 0.5, k + 0.5));
  return x;
}

Vec3 momentum(const emps::Particles3& p, double m) {
  Vec3 P = Vec3::Zero();
  for (std::size_t i = 0; i < p.size(); ++i)
    P += m * Vec3(p.velocity[0][i], p.velocity[1][i], p.velocity[2][i]);
  return P;
}

/// The forces the particles received from triangles [first, last), summed.
Vec3 wall_force(const emps::WallForces3& forces, int first, int last) {
  Vec3 f = Vec3::Zero();
  for (const emps::TriangleForces& face : forces)
    for (std::size_t i = 0; i < face.triangle.size(); ++i)
      if (face.triangle[i] >= first && face.triangle[i] < last) f += face.f[i];
  return f;
}

Vec3 total(const fsi::coupling::InterfaceLoads3& loads) {
  Vec3 f = Vec3::Zero();
  for (const Vec3& fk : loads.f) f += fk;
  return f;
}

} // namespace

TEST_CASE("EMPS 3-D wall forces: the walls' forces are the particles' momentum change, the "
          "interface's loads minus its share, pushing the plate out of the fluid",
          "[apps][emps][3d]") {
  const double l0 = 0.02, h = 6 * l0, L = 6 * l0, dt = 5e-4;
  PlateTank tank(L, h, 3);
  emps::FluidOptions3 o = water(l0, 2.5 * h);
  o.wall.contact.alpha_rep = 1e5; // the contact term in the forces too; no viscous loop
  emps::EmpsFluid3 fluid(o, square_column_lattice(6, 6, l0), tank.walls);
  const double m = o.density * o.volume();
  const double M = m * static_cast<double>(fluid.particles().size());
  const int first = tank.plate->first_triangle(), last = first + tank.plate->triangle_count();
  const int all = static_cast<int>(tank.walls.triangles().node.size());
  fsi::coupling::InterfaceLoads3 loads;
  double momentum_error = 0.0, load_error = 0.0, scale = M * 9.81 * dt;
  Vec3 mean_load = Vec3::Zero();
  const int steps = 60;
  for (int s = 0; s < steps; ++s) {
    const Vec3 before = momentum(fluid.particles(), m);
    fluid.advance(s * dt, dt);
    const Vec3 change = momentum(fluid.particles(), m) - before;
    const emps::WallForces3& f = fluid.triangle_forces();
    // d(sum m v) = dt (M g + sum f_wall): the fluid-fluid terms are antisymmetric in pairs
    momentum_error = std::max(
        momentum_error, (change - dt * (M * o.gravity + wall_force(f, 0, all))).norm() / scale);
    fsi::app::emps_plugin::project_triangle_forces(f, *tank.plate, loads);
    load_error =
        std::max(load_error, (total(loads) + wall_force(f, first, last)).norm() / (M * 9.81));
    mean_load += total(loads) / steps;
  }
  REQUIRE(loads.size() == tank.fe.mesh.node_count());
  WARN("EMPS 3-D wall forces over "
       << steps << " steps: |d(sum m v) - dt (M g + sum f)| / (M g dt) " << momentum_error
       << ", |sum loads + sum f on the plate| / Mg " << load_error
       << "; mean load on the plate / Mg " << (mean_load / (M * 9.81)).transpose());
  CHECK(momentum_error <= 1e-10);
  CHECK(load_error <= 1e-13);
  CHECK(mean_load.z() < -0.5 * M * 9.81); // the water presses the plate down, out of the fluid
  CHECK(std::abs(mean_load.x()) <= 1e-3 * M * 9.81);
  CHECK(std::abs(mean_load.y()) <= 1e-3 * M * 9.81);
}

// The same drop with the shipped wall model and a viscosity: the viscous mirror term (eq. 24) and
// the approach viscosity act at the viscous stage (x^n) and have slots of their own; with them
// the recorded forces are still the walls' whole share, and without them they would not be.
TEST_CASE("EMPS 3-D wall forces: the viscous wall terms' forces complete the particles' momentum "
          "change",
          "[apps][emps][3d]") {
  const double l0 = 0.02, h = 6 * l0, L = 6 * l0, dt = 5e-4;
  PlateTank tank(L, h, 3);
  emps::FluidOptions3 o = water(l0, 2.5 * h);
  emps::apply_wall_preset(o, emps::WallModel::standard); // approach viscosity 0.5
  o.viscosity = 1e-3;
  o.wall.contact.alpha_rep = 1e5;
  emps::EmpsFluid3 fluid(o, square_column_lattice(6, 6, l0), tank.walls);
  const double m = o.density * o.volume();
  const double M = m * static_cast<double>(fluid.particles().size());
  const int all = static_cast<int>(tank.walls.triangles().node.size());
  double momentum_error = 0.0, viscous_share = 0.0;
  const double scale = M * 9.81 * dt;
  for (int s = 0; s < 60; ++s) {
    const Vec3 before = momentum(fluid.particles(), m);
    fluid.advance(s * dt, dt);
    const Vec3 change = momentum(fluid.particles(), m) - before;
    const emps::WallForces3& f = fluid.triangle_forces();
    REQUIRE(f[emps::viscous_slot3].triangle.size() == fluid.owned());
    momentum_error = std::max(
        momentum_error, (change - dt * (M * o.gravity + wall_force(f, 0, all))).norm() / scale);
    Vec3 viscous = Vec3::Zero();
    for (std::size_t k = emps::viscous_slot3; k < emps::wall_slots3; ++k)
      for (const Vec3& fi : f[k].f) viscous += fi;
    viscous_share = std::max(viscous_share, dt * viscous.norm() / scale);
  }
  WARN("EMPS 3-D wall forces with the viscous wall terms over 60 steps: |d(sum m v) - dt (M g + "
       "sum f)| / (M g dt) "
       << momentum_error << "; the viscous slots' largest share " << viscous_share);
  CHECK(momentum_error <= 1e-10);
  CHECK(viscous_share >= 1e-3); // without the viscous slots the balance would miss by this
}

// Still water of depth h on the plate forming the whole floor of the tank (the shipped wall
// model, damped for 0.5 s): the plate's mean load over the last 0.3 s against rho g h A, and the
// side walls' vertical share (the mirror terms of a vertical wall carry the image's vertical
// pressure gradient), which the plate's deficit must match.
TEST_CASE("EMPS 3-D wall forces: report: a still water column's load on a plate",
          "[apps][emps][3d][slow]") {
  const double l0 = 0.02, h = 6 * l0, L = 10 * l0, dt = 5e-4, g = 9.81;
  PlateTank tank(L, h, 5);
  emps::FluidOptions3 o = water(l0, 2.5 * h);
  emps::apply_wall_preset(o, emps::WallModel::standard);
  o.viscosity = 1e-6;
  o.wall.contact.alpha_rep = 1e5;
  o.damping_time = 0.5;
  emps::EmpsFluid3 fluid(o, square_column_lattice(10, 6, l0), tank.walls);
  const double weight = o.density * g * h * L * L; // rho g h A, the column's weight
  const int first = tank.plate->first_triangle();  // the side walls come before the plate
  fsi::coupling::InterfaceLoads3 loads;
  Vec3 plate = Vec3::Zero(), sides = Vec3::Zero(), unrecorded = Vec3::Zero();
  const long steps = 1600, from = 1000;
  const double m = o.density * o.volume(), window = static_cast<double>(steps - from) * dt;
  const Vec3 weight_force = m * static_cast<double>(fluid.particles().size()) * o.gravity;
  Vec3 start = Vec3::Zero();
  for (long s = 0; s < steps; ++s) {
    const Vec3 before = momentum(fluid.particles(), m);
    if (s == from) start = before;
    fluid.advance(static_cast<double>(s) * dt, dt);
    if (s < from) continue;
    const emps::WallForces3& f = fluid.triangle_forces();
    fsi::app::emps_plugin::project_triangle_forces(f, *tank.plate, loads);
    plate += total(loads) / static_cast<double>(steps - from);
    sides -= wall_force(f, 0, first) / static_cast<double>(steps - from);
    // What changed the momentum beyond gravity and the recorded wall forces (the viscous wall
    // terms have their slots), as a mean force over the window.
    unrecorded += (momentum(fluid.particles(), m) - before) / window -
                  dt / window * (weight_force + wall_force(f, 0, std::numeric_limits<int>::max()));
  }
  const Vec3 accelerating = (momentum(fluid.particles(), m) - start) / window;
  const double plate_error = -plate.z() / weight - 1.0;
  const double balance_error = -(plate.z() + sides.z()) / weight - 1.0;
  WARN("still column h = " << h << " m on a " << L << " m square plate ("
                           << fluid.particles().size()
                           << " particles): mean plate load / (rho g h A) - 1 = " << plate_error
                           << ", side walls' vertical share " << -sides.z() / weight
                           << ", (plate + sides) / weight - 1 = " << balance_error
                           << "; over the window dP/dt / weight " << accelerating.z() / weight
                           << ", unrecorded wall share / weight " << unrecorded.z() / weight);
  CHECK(fluid.removed() == 0);
  CHECK(std::abs(plate_error) <= 0.05);
  CHECK(std::abs(unrecorded.z()) <= 1e-12 * weight); // every wall term in eq. 52's record
}
