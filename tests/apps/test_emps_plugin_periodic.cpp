// fluid.periodic_z for fluid.type: emps (issue 43): the shipped periodic slab wraps over the
// tank's depth, its tank has no z faces and runs through the period, its probes count the owned
// particles only (not the images), and bad periodic scenes are refused by file, line and key.
#include "emps/emps_model3.hpp"
#include "fsi/core/error.hpp"
#include "fsi_app/scene.hpp"

#include <catch2/catch.hpp>

#include <string>
#include <utility>
#include <vector>

using namespace fsi;
using namespace fsi::app;

TEST_CASE("apps: the periodic EMPS slab wraps over the tank's depth, its tank has no z faces, "
          "and bad ones are refused",
          "[apps][emps][3d]") {
  const std::string path = FSI_SOURCE_DIR "/data/scenes/dam_break_slab_emps_3d_periodic.yaml";
  const Scene scene = load_scene(path, {});
  emps_plugin::EmpsModel3 model(scene);
  const auto& f = model.fluid();
  CHECK(f.options().periodic_z);
  CHECK(f.options().domain_min.z() == 0.0);
  CHECK(f.options().domain_max.z() == 0.04); // the period: the tank's depth
  CHECK(f.owned() == 20 * 40 * 8);
  CHECK(f.particles().size() > f.owned()); // the images of the layers within reach of a face
  const auto& w = model.walls();
  REQUIRE(w.triangles().size() == 8); // floor, lid and the two x walls
  for (int t = 0; t < 8; ++t) CHECK(w.face_normal(t).z() == 0.0);
  const double r_e = f.options().r_e();
  for (const Vec3& x : w.nodes().x) CHECK(std::abs(x.z() - 0.02) == Approx(0.02 + 4 * r_e));
  ProbeSpec p;
  p.quantity = "particles";
  CHECK(*model.probe(p) == 20 * 40 * 8);
  model.advance(0.0, 1e-5);
  CHECK(*model.probe(p) == 20 * 40 * 8);

  // (overrides, what the one-line message says after "FILE:LINE: ")
  const std::vector<std::pair<std::vector<std::string>, std::string>> bad = {
      {{"fluid.tank.max=[0.8, 0.65, 0.041]"},
       "fluid.periodic_z: the tank's depth 0.041 m is not a whole number of l0 = 0.005 m"},
      {{"fluid.domain={min: [-0.1, -0.1, 0.0], max: [0.9, 0.7, 0.05]}"},
       "fluid.domain: with periodic_z its z range must be the tank's (the period)"},
      {{"fluid.tank_motion={kind: sinusoid, dof: x, amplitude: 0.01, period: 0.5}"},
       "fluid.periodic_z: not available with tank_motion yet"}};
  for (const auto& [sets, what] : bad) {
    INFO(sets.front());
    CHECK_THROWS_WITH(emps_plugin::EmpsModel3(load_scene(path, sets)), Catch::Contains(what));
  }
  // A 2-D scene: the key is 3-D's.
  CHECK_THROWS_WITH(
      load_scene(FSI_SOURCE_DIR "/data/scenes/dam_break_rigid.yaml", {"fluid.periodic_z=true"}),
      Catch::Contains("dam_break_rigid.yaml:") &&
          Catch::Contains("fluid.periodic_z: is a key of 3-D scenes"));
}
