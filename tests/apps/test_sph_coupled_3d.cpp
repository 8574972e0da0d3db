// The 3-D SPH fluid coupled to a T10 plate (SphModel3 on FemModelT10's interface, CoupledModel3):
// the plate replaces the tank's floor (no dummies under it, no water in it), F's loads are the
// boundary points' forces summed to round-off, and a restart continues bitwise.
#include "fem/fem_model_t10.hpp"
#include "fsi_app/coupled_model.hpp"
#include "fsi_app/scene.hpp"
#include "plate_floor_3d.hpp"
#include "sph/sph_model3.hpp"

#include <catch2/catch.hpp>

#include <string>

using namespace fsi;
using namespace fsi::app;

namespace {

// A 0.4 x 0.3 x 0.4 m column (l0 0.05: 384 particles) in a 0.4 x 0.4 m tank whose floor is a
// 0.05 m aluminium plate of 2 x 1 x 2 cells (24 T10), clamped on its four sides, wetted on top.
const std::string column = R"(dimension: 3
gravity: [0.0, -9.81, 0.0]
time: {end: 0.004, dt: 1.0e-3}
output: {interval: 0.004}
fluid:
  type: sph
  density: 1000.0
  viscosity: 1.0e-6
  l0: 0.05
  sound_speed: 20.0
  tank: {min: [0.0, 0.0, 0.0], max: [0.4, 0.5, 0.4]}
  regions:
    - {min: [0.0, 0.0, 0.0], max: [0.4, 0.3, 0.4]}
)" + fsi::test::plate_floor_3d();

const sph::SphFluid3& fluid_of(CoupledModel3& model) {
  return dynamic_cast<sph_plugin::SphModel3&>(model.fluid()).fluid();
}

} // namespace

TEST_CASE("apps: a T10 plate as the 3-D SPH tank's floor, F's loads its points' forces summed",
          "[apps][sph][3d][coupled]") {
  const Scene scene = parse_scene(column, "column.yaml", {});
  const auto plate = find_structure_plugin("fem")->build(scene, 0);
  const InterfaceMesh3& mesh = plate->interface_mesh3();
  sph_plugin::SphModel3 model(scene, {mesh});
  const sph::SphFluid3& f = model.fluid();
  CHECK(f.particles().size() == 8 * 6 * 8);
  // Under the plate's top no tank dummy: the boundary points stand there (4 layers of 8 x 8).
  const auto& w = f.walls();
  std::size_t dummies_under = 0;
  for (std::size_t a = 0; a < model.first_point(); ++a)
    if (w.x[1][a] < 0.0 && w.x[0][a] > 0.0 && w.x[0][a] < 0.4 && w.x[2][a] > 0.0 && w.x[2][a] < 0.4)
      ++dummies_under;
  CHECK(dummies_under == 0);
  CHECK(w.size() - model.first_point() == 4 * 8 * 8);
  // The still column settles for 40 acoustic steps, then one coupler step of one acoustic step:
  // the nodal loads sum to the points' forces of that step.
  coupling::FluidSolver3& F = model.coupling_solver3();
  F.set_interface_motion(fsi::test::at_rest(mesh));
  for (int k = 0; k < 40; ++k) F.advance(f.time(), f.next_dt());
  F.advance(f.time(), f.next_dt());
  Vec3 loads = Vec3::Zero(), points = Vec3::Zero();
  for (const Vec3& q : F.interface_loads().f) loads += q;
  for (std::size_t a = model.first_point(); a < w.size(); ++a) points += f.wall_force(a);
  INFO("loads " << loads.transpose() << " N, points " << points.transpose() << " N");
  CHECK(loads.y() < 0.0); // the water pushes the plate down
  CHECK((loads - points).norm() <= 1e-13 * points.norm());
}

TEST_CASE("apps: the coupled 3-D SPH + T10 model restarts bitwise", "[apps][sph][3d][coupled]") {
  namespace test = fsi::test; // not fsi::app::test, in reach in the unity build
  test::check_restart_bitwise(parse_scene(column, "column.yaml", {}),
                              [](CoupledModel3& whole, CoupledModel3& resumed) {
                                const auto& a = fluid_of(whole).particles();
                                const auto& b = fluid_of(resumed).particles();
                                REQUIRE(a.size() == b.size());
                                for (int c = 0; c < 3; ++c) {
                                  CHECK(a.x[c] == b.x[c]);
                                  CHECK(a.v[c] == b.v[c]);
                                }
                                CHECK(a.rho == b.rho);
                              });
}
