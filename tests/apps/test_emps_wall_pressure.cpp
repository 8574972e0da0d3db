// The pressure a wall sees at a point of a triangle (emps_plugin::WallPointPressure, issue 43):
// the wall's own force per area over the point's plane, against still water in a closed box tank
// of 12 triangles (the 3-D hydrostatic tank's recipe, damped): at the floor's centre rho g H (the
// column's weight per area), pushing the floor out of the fluid; the weight's integral over a
// whole disc and a disc cut by an edge; a point off every wall refused.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <vector>

#include "emps/wall_point_pressure.hpp"
#include "fsi/core/error.hpp"
#include "geometry_erp/box_walls.hpp"

using fsi::Vec3;
namespace emps = fsi::emps;
namespace erp = fsi::erp;
using fsi::app::emps_plugin::WallPointPressure;

namespace {

std::vector<Vec3> box_lattice(int nx, int ny, int nz, double l0) {
  std::vector<Vec3> x;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) x.push_back(l0 * Vec3(i + 0.5, j + 0.5, k + 0.5));
  return x;
}

} // namespace

TEST_CASE("EMPS 3-D wall pressure: the weight's integral over a whole disc and over one cut by "
          "an edge; a point off the walls refused",
          "[apps][emps][3d]") {
  erp::TriangleWallSet walls;
  erp::add_box_tank(walls, Vec3::Zero(), Vec3(1.0, 1.0, 1.0), false, 0);
  const double R = 0.1, disc = std::numbers::pi * R * R / 7.0; // int (1-q)^4 (1+4q) dA
  const WallPointPressure centre(walls, Vec3(0.5, 0.5, 0.0), R);
  CHECK_THAT(centre.area(), Catch::Matchers::WithinRel(disc, 1e-3));
  CHECK(centre.normal().isApprox(Vec3(0, 0, 1), 1e-15)); // the floor's fluid normal
  // On the floor's edge x = 0: half the disc, the wall x = 0 not in the floor's plane.
  const WallPointPressure edge(walls, Vec3(0.0, 0.5, 0.0), R);
  CHECK_THAT(edge.area(), Catch::Matchers::WithinRel(0.5 * disc, 1e-3));
  CHECK_THROWS_AS(WallPointPressure(walls, Vec3(0.5, 0.5, 0.01), R), fsi::InputError);
}

// Still water of depth H = 10 l0 in a closed 10 l0 x 10 l0 x 20 l0 box tank (z up; the shipped
// wall model, alpha_rep 1e5, c = 15 m/s, damped for 0.5 s), the wall pressure averaged over the
// 0.5 s after the damping: at the floor's centre rho g H (the column above each floor particle
// weighs rho g H l0^2), the force pushing the floor out of the fluid (along -z).
TEST_CASE("EMPS 3-D wall pressure: still water's floor at its centre is rho g H, pushed out of "
          "the fluid",
          "[apps][emps][3d][long]") {
  const double l0 = 0.02, g = 9.81, dt = 5e-4;
  const int n = 10;
  const double L = n * l0, H = n * l0;
  erp::TriangleWallSet walls;
  erp::add_box_tank(walls, Vec3::Zero(), Vec3(L, L, 2 * H), false, 0);
  emps::FluidOptions3 o;
  o.density = 1000.0;
  o.l0 = l0;
  o.sound_speed = 15.0;
  o.gravity = Vec3(0.0, 0.0, -g);
  o.domain_min = Vec3::Constant(-0.05);
  o.domain_max = Vec3::Constant(2 * H + 0.05);
  emps::apply_wall_preset(o, emps::WallModel::standard);
  o.viscosity = 1e-6;
  o.wall.contact.alpha_rep = 1e5;
  o.damping_time = 0.5;
  emps::EmpsFluid3 fluid(o, box_lattice(n, n, n, l0), walls);
  const double R = 3 * l0;
  const WallPointPressure floor(walls, Vec3(L / 2, L / 2, 0.0), R);
  const WallPointPressure side(walls, Vec3(0.0, L / 2, H / 2), R); // mid-depth on x = 0
  const long steps = 2000, from = 1000;
  Vec3 f_floor = Vec3::Zero(), f_side = Vec3::Zero();
  for (long s = 0; s < steps; ++s) {
    fluid.advance(static_cast<double>(s) * dt, dt);
    if (s < from) continue;
    f_floor += floor.weighted_force(fluid.triangle_forces()) / static_cast<double>(steps - from);
    f_side += side.weighted_force(fluid.triangle_forces()) / static_cast<double>(steps - from);
  }
  const double p_floor = floor.pressure(f_floor), p_side = side.pressure(f_side);
  const double rho_g = o.density * g;
  WARN("still water H = " << H << " m: floor centre " << p_floor << " Pa, "
                          << 100.0 * (p_floor / (rho_g * H) - 1.0) << " % of rho g H = "
                          << rho_g * H << " Pa; side wall at mid-depth " << p_side << " Pa, "
                          << 100.0 * (p_side / (rho_g * H / 2) - 1.0) << " % of rho g H/2; floor's "
                          << "weighted force " << f_floor.transpose() << " N");
  CHECK(fluid.removed() == 0);
  CHECK_THAT(p_floor, Catch::Matchers::WithinRel(rho_g * H, 0.01));
  CHECK(f_floor.z() < 0.0); // the wall receives -f: pushed along -z, out of the fluid
  CHECK(f_side.x() < 0.0);  // the wall x = 0 pushed along -x
}
