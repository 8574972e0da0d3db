// The 3-D EMPS fluid coupled to a T10 plate (EmpsModel3 on FemModelT10's interface,
// CoupledModel3): the plate replaces the tank's floor (the two floor triangles it covers are left
// out; a partial cover is refused), F's loads are minus the fluid's wall forces on the plate's
// triangles to round-off, and a restart continues bitwise.
#include "emps/emps_model3.hpp"
#include "emps/tank_cover.hpp"
#include "fsi/core/error.hpp"
#include "fsi_app/coupled_model.hpp"
#include "fsi_app/scene.hpp"
#include "fsi_app/solver_plugin.hpp"
#include "plate_floor_3d.hpp"

#include <catch2/catch.hpp>

#include <string>

using namespace fsi;
using namespace fsi::app;

namespace {

// A 0.4 x 0.3 x 0.4 m column (l0 0.05: 384 particles) in a closed 0.4 x 0.5 x 0.4 m tank whose
// floor is a 0.05 m aluminium plate of 2 x 1 x 2 cells (24 T10), clamped on its four sides,
// wetted on top; the EMPS keys of hydrostatic_tank_emps_3d (c dt / l0 = 0.4).
std::string column(const std::string& plate_width = "0.4") {
  return R"(dimension: 3
gravity: [0.0, -9.81, 0.0]
time: {end: 0.004, dt: 1.0e-3}
output: {interval: 0.004}
fluid:
  type: emps
  density: 1000.0
  viscosity: 1.0e-6
  l0: 0.05
  re_over_l0: 3.1
  sound_speed: 20.0
  alpha_rep: 1.0e5
  wall_model: default
  tank: {min: [0.0, 0.0, 0.0], max: [0.4, 0.5, 0.4]}
  regions:
    - {min: [0.0, 0.0, 0.0], max: [0.4, 0.3, 0.4]}
)" + test::plate_floor_3d(plate_width);
}

const emps::EmpsFluid3& fluid_of(CoupledModel3& model) {
  return dynamic_cast<emps_plugin::EmpsModel3&>(model.fluid()).fluid();
}

} // namespace

TEST_CASE("apps: a T10 plate as the 3-D EMPS tank's floor, F's loads minus its triangles' forces",
          "[apps][emps][3d][coupled]") {
  const Scene scene = parse_scene(column(), "column.yaml", {});
  const auto plate = find_structure_plugin("fem")->build(scene, 0);
  const InterfaceMesh3& mesh = plate->interface_mesh3();
  emps_plugin::EmpsModel3 model(scene, {mesh});
  const emps::EmpsFluid3& f = model.fluid();
  CHECK(f.particles().size() == 8 * 6 * 8);
  // The tank's two floor triangles (y = 0, facing up) are left out: the plate's stand there.
  const erp::TriangleWallSet& w = model.walls();
  REQUIRE(model.interface_triangles().size() == 1);
  const erp::InterfaceTriangles& plate_walls = model.interface_triangles().front();
  CHECK(plate_walls.first_triangle() == 10);
  CHECK(plate_walls.triangle_count() == 4 * static_cast<int>(mesh.faces.size()));
  CHECK(static_cast<int>(w.triangles().size()) == 10 + plate_walls.triangle_count());
  int floors = 0, up = 0;
  for (int t = 0; t < static_cast<int>(w.triangles().size()); ++t) {
    const bool is_up = w.face_normal(t).isApprox(Vec3(0.0, 1.0, 0.0), 1e-12);
    up += is_up;
    floors += is_up && w.triangles().group[static_cast<std::size_t>(t)] == 0;
  }
  CHECK(floors == 0);
  CHECK(up == plate_walls.triangle_count());
  // A few steps of the column at rest on the plate: the nodal loads sum to minus the particles'
  // wall forces on the plate's triangles.
  coupling::FluidSolver3& F = model.coupling_solver3();
  F.set_interface_motion(test::at_rest(mesh));
  for (int k = 0; k < 5; ++k) F.advance(k * 1e-3, 1e-3);
  Vec3 loads = Vec3::Zero(), forces = Vec3::Zero();
  for (const Vec3& q : F.interface_loads().f) loads += q;
  const int first = plate_walls.first_triangle(), last = first + plate_walls.triangle_count();
  std::size_t on_plate = 0;
  for (const emps::TriangleForces& face : f.triangle_forces())
    for (std::size_t i = 0; i < face.triangle.size(); ++i)
      if (face.triangle[i] >= first && face.triangle[i] < last) forces += face.f[i], ++on_plate;
  INFO("loads " << loads.transpose() << " N, forces " << forces.transpose() << " N on " << on_plate
                << " particle faces");
  CHECK(on_plate > 0);
  CHECK(loads.y() < 0.0); // the water pushes the plate down
  CHECK((loads + forces).norm() <= 1e-13 * forces.norm());
}

TEST_CASE("apps: a tank triangle covered wholly is left out, partly is refused",
          "[apps][emps][3d][coupled]") {
  // The unit square z = 0 (two triangles facing +z) under four faces of the square: covered.
  const std::vector<Vec3> points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
  const std::vector<std::array<int, 3>> square = {{0, 1, 2}, {0, 2, 3}};
  InterfaceMesh3 cover;
  cover.order = 1;
  cover.X0 = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0), Vec3(0.5, 0.5, 1e-9)};
  cover.faces = {{0, 1, 4, 0, 0, 0}, {1, 2, 4, 0, 0, 0}, {2, 3, 4, 0, 0, 0}, {3, 0, 4, 0, 0, 0}};
  CHECK(emps_plugin::uncovered_triangles(points, square, {cover}, 1e-8).empty());
  // Its centre lifted beyond the tolerance: the faces are not in the plane, nothing is covered.
  InterfaceMesh3 lifted = cover;
  lifted.X0[4].z() = 1e-6;
  CHECK(emps_plugin::uncovered_triangles(points, square, {lifted}, 1e-8) == square);
  // Half the square: triangle 1 (0, 1, 2) a quarter covered.
  InterfaceMesh3 half = cover;
  half.faces = {{0, 1, 4, 0, 0, 0}, {3, 0, 4, 0, 0, 0}};
  CHECK_THROWS_WITH(emps_plugin::uncovered_triangles(points, square, {half}, 1e-8),
                    "tank triangle 1 is 50 % covered by interface 0 (a structure on the tank's "
                    "wall must cover its triangles wholly or not at all)");
  // In a scene: a plate 0.3 m wide under the 0.4 m tank, refused at fluid.tank before any run.
  const Scene scene = parse_scene(column("0.3"), "column.yaml", {});
  const StructureOutline o = find_structure_plugin("fem")->validate(scene, 0);
  CHECK_THROWS_WITH(emps_plugin::validate3(scene, {o.interface3}),
                    Catch::StartsWith("column.yaml:") &&
                        Catch::Contains(": fluid.tank: tank triangle 3 is ") &&
                        Catch::Contains("% covered by interface 0"));
}

TEST_CASE("apps: the coupled 3-D EMPS + T10 model restarts bitwise", "[apps][emps][3d][coupled]") {
  test::check_restart_bitwise(parse_scene(column(), "column.yaml", {}),
                              [](CoupledModel3& whole, CoupledModel3& resumed) {
                                const auto& a = fluid_of(whole).particles();
                                const auto& b = fluid_of(resumed).particles();
                                REQUIRE(a.size() == b.size());
                                for (int c = 0; c < 3; ++c) {
                                  CHECK(a.position[c] == b.position[c]);
                                  CHECK(a.velocity[c] == b.velocity[c]);
                                }
                                CHECK(a.p == b.p);
                              });
}
