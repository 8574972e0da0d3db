// fluid.type: sph in a 3-D scene (issue 45): the shipped hydrostatic_tank_sph_3d builds the open
// tank's dummies with y up (the 3-D unit test's tank, z up, has as many) and answers its 3-D
// probes; the column, symmetric in x and z, keeps no z velocity.
#include "fsi_app/scene.hpp"
#include "sph/sph_model3.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace fsi;
using namespace fsi::app;

TEST_CASE("apps: the 3-D SPH scene's tank is open at max.y, its probes read in 3-D",
          "[apps][sph][3d]") {
  const Scene scene = load_scene(FSI_SOURCE_DIR "/data/scenes/hydrostatic_tank_sph_3d.yaml", {});
  REQUIRE(scene.dimension == 3);
  sph_plugin::SphModel3 model(scene);
  const auto& f = model.fluid();
  CHECK(f.particles().size() == 2000);
  const auto& w = f.walls();
  CHECK(w.size() == 7420); // test_sph_3d.cpp's 0.2 x 0.2 x 0.6 tank, z up
  const auto top = std::max_element(w.x[1].begin(), w.x[1].end());
  CHECK(*top < 0.6);
  std::size_t under_floor = 0;
  for (std::size_t a = 0; a < w.size(); ++a)
    if (w.x[1][a] < 0.0 && w.x[0][a] > 0.0 && w.x[0][a] < 0.2 && w.x[2][a] > 0.0 &&
        w.x[2][a] < 0.2) {
      ++under_floor;
      CHECK(w.n[1][a] == 1.0); // into the fluid, up
    }
  CHECK(under_floor == 4 * 10 * 10);
  model.advance(0.0, 0.02);
  ProbeSpec p;
  p.point3 = Vec3(0.1, 0.2, 0.1);
  p.quantity = "velocity_y";
  const double vy = *model.probe(p);
  p.quantity = "velocity_z";
  const double vz = *model.probe(p);
  INFO("vy " << vy << ", vz " << vz);
  CHECK(vy < -1e-3); // the released column falls while its pressure builds
  CHECK(std::abs(vz) < 1e-9 * std::abs(vy));
  p.quantity = "pressure";
  CHECK(*model.probe(p) > 0.0);
}

TEST_CASE("apps: a periodic_z slab has no walls behind its z faces, and bad ones are refused",
          "[apps][sph][3d]") {
  const std::string path = FSI_SOURCE_DIR "/data/scenes/dam_break_slab_sph_3d.yaml";
  const Scene scene = load_scene(path, {});
  sph_plugin::SphModel3 model(scene);
  const auto& f = model.fluid();
  CHECK(f.options().periodic_z);
  CHECK(f.options().domain_min.z() == 0.0);
  CHECK(f.options().domain_max.z() == 0.02); // the period: the tank's depth
  CHECK(f.particles().size() == 40 * 80 * 8);
  const auto& w = f.walls();
  for (std::size_t a = 0; a < w.size(); ++a) {
    CHECK(w.n[2][a] == 0.0);
    CHECK(w.x[2][a] > 0.0);
    CHECK(w.x[2][a] < 0.02);
  }
  // (overrides, what the one-line message says after "FILE:LINE: ")
  const std::vector<std::pair<std::vector<std::string>, std::string>> bad = {
      {{"fluid.tank.max=[0.8, 0.5, 0.021]"},
       "fluid.periodic_z: the tank's depth 0.021 m is not a whole number of l0 = 0.0025 m"},
      {{"fluid.domain={min: [-0.1, -0.1, 0.0], max: [0.9, 0.6, 0.03]}"},
       "fluid.domain: with periodic_z its z range must be the tank's (the period)"},
      {{"fluid.tank.max=[0.8, 0.5, 0.015]", "fluid.regions[0].max=[0.1, 0.2, 0.015]"},
       "periodic length z"}};
  for (const auto& [sets, what] : bad) {
    INFO(sets.front());
    CHECK_THROWS_WITH(sph_plugin::SphModel3(load_scene(path, sets)), Catch::Contains(what));
  }
}
