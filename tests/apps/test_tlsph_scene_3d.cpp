// structures[].type: tlsph in a 3-D scene (issue 45): a box region filled at dp, clamped boxes,
// gravity, probes at 3-D points; the FE box mesh read as the TL-SPH box (clamped sides continued
// kClampRows dp outwards); what is 2-D only refused naming file, line and key.
#include "fsi/core/error.hpp"
#include "fsi_app/scene.hpp"
#include "scene_error.hpp"
#include "structure_geometry.hpp"
#include "tlsph/tlsph_model3.hpp"
#include "tlsph/tlsph_spec.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

using namespace fsi;
using namespace fsi::app;

namespace {

// The FE cantilever box of data/scenes/cantilever_3d.yaml, coarser, with a tip probe.
const std::string cantilever_box_scene = R"(dimension: 3
gravity: [0.0, -9.81, 0.0]
time: {end: 1.0e-4, dt: 1.0e-4}
output:
  interval: 1.0e-4
  probes:
    - {name: tip_y, quantity: displacement_y, structure: beam, point: [1.0, 0.05, 0.05]}
    - {name: tip_z, quantity: displacement_z, structure: beam, point: [1.0, 0.05, 0.05]}
structures:
  - name: beam
    type: tlsph
    mesh: {kind: box, origin: [0, 0, 0], width: 1.0, height: 0.1, depth: 0.1,
           elements_x: 20, elements_y: 2, elements_z: 2}
    material: {youngs_modulus: 1.0e8, poisson_ratio: 0.3, density: 1000.0}
    clamped: [left]
)";

} // namespace

TEST_CASE("tlsph 3-D scene: the FE box is the TL-SPH box, its clamped side a support",
          "[apps][tlsph][3d]") {
  const Scene s = parse_scene(cantilever_box_scene, "b.yaml", {});
  const auto& t = s.structures[0].as<tlsph_plugin::TlsphSpec>();
  const double dp = 0.025; // the T10 node spacing: height / (2 elements_y)
  CHECK(t.options.dp == dp);
  CHECK(t.box.min.isApprox(Vec3(-kClampRows * dp, 0.0, 0.0)));
  CHECK(t.box.max.isApprox(Vec3(1.0, 0.1, 0.1)));
  REQUIRE(t.clamped3.size() == 1);
  CHECK(t.clamped3[0].min.isApprox(t.box.min));
  CHECK(t.clamped3[0].max.isApprox(Vec3(0.0, 0.1, 0.1)));
}

TEST_CASE("tlsph 3-D scene: the tip falls freely until the clamp's wave reaches it",
          "[apps][tlsph][3d]") {
  const Scene s = parse_scene(cantilever_box_scene, "b.yaml", {});
  tlsph_plugin::TlsphModel3 model(s, s.structures[0]);
  const double t = 1.0e-4; // the wave from the clamp (c_s = 289 m/s) travels 0.03 m, 1.2 dp
  model.advance(0.0, t);
  // Unstrained, the particles nearest the tip move as a rigid body: u_y = -g t^2 / 2.
  CHECK(std::abs(*model.probe(s.output.probes[0]) + 9.81 * t * t / 2.0) < 1e-12);
  CHECK(std::abs(*model.probe(s.output.probes[1])) < 1e-15);
}

TEST_CASE("tlsph 3-D scene: what is 2-D only is refused naming the key", "[apps][tlsph][3d]") {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"structures[0].interface=[x+]",
       "structures[0].interface: no face of the box is named 'x+' (left, right, bottom, top, back, "
       "front)"},
      {"structures[0].interface_particles=true",
       "structures[0].interface_particles: is 2-D only (a 3-D TL-SPH solid couples through its "
       "box's faces)"},
      {"structures[0].dp=0.05",
       "structures[0].dp: fewer than 3 particles across the region (1.200000 x 0.100000 x "
       "0.100000 m)"},
  };
  for (const auto& [set, what] : cases) {
    INFO(set);
    CHECK(test::scene_text_error(cantilever_box_scene, "b.yaml", {set}) ==
          "b.yaml: --set " + set + ": " + what);
  }
  std::string region = cantilever_box_scene.substr(0, cantilever_box_scene.find("    mesh:")) +
                       "    region: {polygon: [[0, 0], [1, 0], [1, 1]]}\n    dp: 0.025\n"
                       "    material: {youngs_modulus: 1.0e8, poisson_ratio: 0.3, density: "
                       "1000.0}\n";
  CHECK(test::scene_text_error(region, "b.yaml", {}) ==
        "b.yaml:12: structures[0].region.polygon: is 2-D only (a 3-D region is a box: min, max)");
  CHECK(
      test::scene_text_error(cantilever_box_scene + "    interface: [front, up]\n", "b.yaml", {}) ==
      "b.yaml:16: structures[0].interface: no face of the box is named 'up' (left, right, "
      "bottom, top, back, front)");
}

TEST_CASE("tlsph 3-D scene: interface names the box's faces as the fem type does",
          "[apps][tlsph][3d]") {
  // The beam's faces x = 1 (right) and y = 0.1 (top) over 44 x 4 x 4 particles (the box continued
  // 4 dp into the clamp at x < 0): 6 x 6 nodes on the one, 46 x 6 on the other, 6 shared.
  const Scene s = parse_scene(cantilever_box_scene + "    interface: [right, top]\n", "b.yaml", {});
  tlsph_plugin::TlsphModel3 model(s, s.structures[0]);
  const InterfaceMesh3& mesh = model.interface_mesh3();
  CHECK(mesh.node_count() == 6 * 6 + 46 * 6 - 6);
  double x_max = 0.0, y_min = 1.0;
  for (const Vec3& X : mesh.X0) x_max = std::max(x_max, X.x()), y_min = std::min(y_min, X.y());
  CHECK(std::abs(x_max - 1.0) < 1e-15);
  CHECK(y_min == 0.0); // the right face reaches down to y = 0
  const auto x = model.coupling_solver3().interface_motion().x; // at rest: the nodes at X0
  double moved = 0.0;
  for (std::size_t k = 0; k < x.size(); ++k) moved = std::max(moved, (x[k] - mesh.X0[k]).norm());
  CHECK(moved < 1e-15);
}
