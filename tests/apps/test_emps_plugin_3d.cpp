// fluid.type: emps in a 3-D scene (issue 43): the shipped hydrostatic_tank_emps_3d builds its
// closed box tank of 12 triangles (or reads it from an STL file, to the same run), answers its
// probes, continues bitwise from a checkpoint, and what 3-D does not have yet is refused by name.
#include "emps/emps_model3.hpp"
#include "fsi/core/error.hpp"
#include "fsi/core/state_archive.hpp"
#include "fsi_app/scene.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <tuple>

using namespace fsi;
using namespace fsi::app;

namespace {

const std::string kScene = FSI_SOURCE_DIR "/data/scenes/hydrostatic_tank_emps_3d.yaml";
const std::string kStlScene = FSI_SOURCE_DIR "/data/scenes/hydrostatic_tank_emps_3d_stl.yaml";
constexpr double kDt = 5e-4; // the scene's step

double probe(const emps_plugin::EmpsModel3& model, const std::string& quantity) {
  ProbeSpec p;
  p.quantity = quantity;
  p.point3 = Vec3(0.1, 0.01, 0.1);
  p.box3_min = Vec3::Zero(), p.box3_max = Vec3(0.2, 0.02, 0.2);
  return *model.probe(p);
}

void advance(emps_plugin::EmpsModel3& model, int from, int steps) {
  for (int s = from; s < from + steps; ++s) model.advance(s * kDt, kDt);
}

} // namespace

TEST_CASE("apps: the 3-D EMPS scene's tank is 12 triangles facing the water, its probes read in "
          "3-D",
          "[apps][emps][3d]") {
  const Scene scene = load_scene(kScene, {});
  REQUIRE(scene.dimension == 3);
  emps_plugin::EmpsModel3 model(scene);
  const auto& f = model.fluid();
  CHECK(f.particles().size() == 1000);
  REQUIRE(model.walls().triangles().size() == 12);
  int floor = 0;
  for (int t = 0; t < 12; ++t)
    floor += model.walls().face_normal(t) == Vec3(0.0, 1.0, 0.0); // into the water, up
  CHECK(floor == 2);
  // At rest on the lattice: the nearest centres sit l0/2 from the walls, the interior of the
  // bottom layer has pnd = n0 (the floor's virtual lattice, eq. 20).
  CHECK(probe(model, "wall_gap") == Approx(0.01).epsilon(1e-12));
  CHECK(probe(model, "particles") == 1000.0);
  const auto& p = f.particles();
  for (std::size_t i = 0; i < p.size(); ++i)
    if (std::abs(p.position[1][i] - 0.01) < 1e-9 && std::abs(p.position[0][i] - 0.09) < 1e-9 &&
        std::abs(p.position[2][i] - 0.09) < 1e-9)
      CHECK(std::abs(p.pnd[i] / f.n0() - 1.0) < 1e-12);
  advance(model, 0, 4);
  CHECK(probe(model, "kinetic_energy") > 0.0);
  CHECK(probe(model, "mean_speed") > 0.0);
  CHECK(probe(model, "mean_pressure") > 0.0);
  CHECK(probe(model, "pressure") > 0.0);
  CHECK(probe(model, "wall_gap") > 0.0);
  CHECK(probe(model, "particles") == 1000.0);
}

TEST_CASE("apps: the 3-D EMPS tank read from its STL file runs as the box of keys",
          "[apps][emps][3d]") {
  emps_plugin::EmpsModel3 box(load_scene(kScene, {}));
  emps_plugin::EmpsModel3 stl(load_scene(kStlScene, {}));
  CHECK(stl.walls().triangles().size() == 12);
  advance(box, 0, 4);
  advance(stl, 0, 4);
  const auto &a = box.fluid().particles(), &b = stl.fluid().particles();
  REQUIRE(a.size() == b.size());
  double worst = 0.0; // the triangles differ in order and diagonals: round-off, not bitwise
  for (std::size_t i = 0; i < a.size(); ++i)
    for (int c = 0; c < 3; ++c)
      worst = std::max(worst, std::abs(a.position[c][i] - b.position[c][i]));
  INFO("largest position difference " << worst << " m");
  CHECK(worst < 1e-12);
}

TEST_CASE("apps: a 3-D EMPS run continued from its checkpoint is bitwise the run that was not "
          "interrupted",
          "[apps][emps][3d]") {
  const Scene scene = load_scene(kScene, {});
  emps_plugin::EmpsModel3 whole(scene), first(scene), second(scene);
  advance(whole, 0, 6);
  advance(first, 0, 3);
  StateArchive archive;
  first.write_state(archive);
  second.read_state(archive);
  advance(second, 3, 3);
  const auto &a = whole.fluid().particles(), &b = second.fluid().particles();
  REQUIRE(a.size() == b.size());
  std::size_t differ = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (int c = 0; c < 3; ++c)
      differ += a.position[c][i] != b.position[c][i] || a.velocity[c][i] != b.velocity[c][i];
    differ += a.p[i] != b.p[i] || a.pnd[i] != b.pnd[i];
  }
  CHECK(differ == 0);
}

TEST_CASE("apps: what a 3-D EMPS scene does not have yet, and bad tanks, are refused by name",
          "[apps][emps][3d]") {
  const auto dir = std::filesystem::temp_directory_path();
  const std::string flipped = (dir / "test_emps_plugin_3d_flipped.stl").string();
  const std::string broken = (dir / "test_emps_plugin_3d_broken.stl").string();
  { // the shipped tank with every facet's vertex order and normal reversed: facing out
    std::ifstream in(FSI_SOURCE_DIR "/data/meshes/hydrostatic_tank_emps_3d.stl");
    std::ofstream out(flipped);
    std::string line, a, b;
    while (std::getline(in, line)) {
      if (line.find("facet normal") != std::string::npos) {
        std::istringstream n(line.substr(line.find("normal") + 6));
        double x, y, z;
        n >> x >> y >> z;
        out << "facet normal " << -x << ' ' << -y << ' ' << -z << '\n';
      } else if (line.find("vertex") != std::string::npos) {
        if (a.empty())
          a = line;
        else if (b.empty())
          b = line;
        else
          out << line << '\n' << b << '\n' << a << '\n', a.clear(), b.clear();
      } else
        out << line << '\n';
    }
    std::ofstream(broken) << "solid t\n  facet normal 0 0 1\n    outer loop\n      vertex 0 0\n";
  }
  // (the scene, overrides, what the one-line message says after "FILE:LINE: ")
  const std::vector<std::tuple<std::string, std::vector<std::string>, std::string>> bad = {
      {kScene, {"fluid.convex_corners=true"}, "fluid.convex_corners: not available in 3-D yet"},
      {kScene,
       {"fluid.wall_contact=viscous"},
       "fluid.wall_contact: 'viscous' is not available in 3-D yet"},
      {kScene,
       {"fluid.wall_pressure=neighbours"},
       "fluid.wall_pressure: 'neighbours' is not available in 3-D yet"},
      {kScene,
       {"fluid.tank_file=../meshes/hydrostatic_tank_emps_3d.stl"},
       "fluid.tank_file: give either tank (a box) or tank_file (a surface), not both"},
      {kStlScene, {"fluid.tank_file=no_such.stl"}, "fluid.tank_file: file not found"},
      {kStlScene,
       {"fluid.tank_file=" + flipped},
       flipped + ": the fluid at (0.01, 0.01, 0.01) m lies behind facet"},
      {kStlScene, {"fluid.tank_file=" + broken}, broken + ":4:"},
      {kScene,
       {"output.probes[4].point=[0.1, 0.01, 0.5]"},
       "output.probes[4].point: the point is outside the fluid domain"},
      {kScene,
       {"walls=[{name: w, polyline: [[0, 0], [1, 0]]}]"},
       "3-D wall polylines are not yet available"},
      {kScene,
       {"fluid.regions[0].max=[0.2, 0.2, 0.3]"},
       "fluid.regions: fluid region 0 reaches outside the tank"}};
  for (const auto& [file, sets, what] : bad) {
    INFO(sets.front());
    CHECK_THROWS_AS(emps_plugin::EmpsModel3(load_scene(file, sets)), InputError);
    CHECK_THROWS_WITH(emps_plugin::EmpsModel3(load_scene(file, sets)), Catch::Contains(what));
  }
  std::filesystem::remove(flipped);
  std::filesystem::remove(broken);
}
