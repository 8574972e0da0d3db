// structures[].type: tlsph regions: a rectangle (min, max) or a counter-clockwise polygon with a
// tag per edge (issue 19: "rectangles and polygons"). The polygon form of a rectangle builds the
// same solid; a trapezoid holds exactly the lattice points inside it and its interface lies on the
// tagged edge; a clockwise polygon, a tag count that does not fit and an unknown interface tag
// are one-line errors naming the key.
#include "fsi/core/error.hpp"
#include "fsi_app/scene.hpp"
#include "tlsph/tlsph_model.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <string>

using namespace fsi;
using namespace fsi::app;
using fsi::app::tlsph_plugin::TlsphModel;

namespace {

std::string scene_with(const std::string& region, const std::string& interface) {
  return "name: solid\ntime: {end: 0.001, dt: 1.0e-5}\noutput: {interval: 0.001}\n"
         "structures:\n  - name: block\n    type: tlsph\n    region: " +
         region +
         "\n    dp: 0.002\n    material: {youngs_modulus: 1.0e6, poisson_ratio: 0.3, density: "
         "1000.0}\n    interface: " +
         interface + "\n";
}

std::string error_of(const std::string& text) {
  try {
    parse_scene(text, "scene.yaml", {});
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

} // namespace

TEST_CASE("tlsph plug-in: a rectangle as a polygon builds the same solid", "[apps][tlsph]") {
  const Scene box = parse_scene(scene_with("{min: [0.0, 0.0], max: [0.02, 0.04]}", "[left, top]"),
                                "scene.yaml", {});
  const Scene polygon = parse_scene(
      scene_with("{polygon: [[0.0, 0.0], [0.02, 0.0], [0.02, 0.04], [0.0, 0.04]], tags: "
                 "[bottom, right, top, left]}",
                 "[left, top]"),
      "scene.yaml", {});
  TlsphModel a(box, box.structures.front()), b(polygon, polygon.structures.front());
  CHECK(a.solid().size() == 200);
  CHECK(b.solid().size() == a.solid().size());
  REQUIRE(b.interface_mesh().node_count() == a.interface_mesh().node_count());
  for (std::size_t k = 0; k < a.interface_mesh().node_count(); ++k)
    CHECK(b.interface_mesh().X0[k] == a.interface_mesh().X0[k]);
  CHECK(b.occupied_area() == a.occupied_area());
}

TEST_CASE("tlsph plug-in: a trapezoid holds its lattice points, its interface on the tagged edge",
          "[apps][tlsph]") {
  // Vertices (0, 0), (0.04, 0), (0.03, 0.02), (0, 0.02): the slope is x = 0.04 - y / 2.
  const Scene scene = parse_scene(
      scene_with("{polygon: [[0.0, 0.0], [0.04, 0.0], [0.03, 0.02], [0.0, 0.02]], tags: "
                 "[bottom, slope, top, left]}",
                 "[slope]"),
      "scene.yaml", {});
  TlsphModel model(scene, scene.structures.front());
  const double dp = 0.002;
  std::size_t inside = 0;
  for (int j = 0; j < 10; ++j)
    for (int i = 0; i < 20; ++i)
      if ((i + 0.5) * dp < 0.04 - 0.5 * (j + 0.5) * dp) ++inside;
  CHECK(model.solid().size() == inside);
  const InterfaceMesh& mesh = model.interface_mesh();
  REQUIRE(mesh.node_count() >= 10);
  for (const Vec2& X : mesh.X0) {
    INFO("interface node (" << X.x() << ", " << X.y() << ")");
    CHECK(std::abs(X.x() + 0.5 * X.y() - 0.04) < 1e-12);
    CHECK(X.y() >= -1e-12);
    CHECK(X.y() <= 0.02 + 1e-12);
  }
}

TEST_CASE("tlsph plug-in: bad polygon regions are one-line errors naming the key",
          "[apps][tlsph]") {
  const std::string clockwise = error_of(
      scene_with("{polygon: [[0.0, 0.0], [0.0, 0.02], [0.04, 0.02], [0.04, 0.0]]}", "[boundary]"));
  CHECK(clockwise.find("scene.yaml:") == 0);
  CHECK(clockwise.find("structures[0].region.polygon: must be counter-clockwise") !=
        std::string::npos);
  const std::string tags = error_of(
      scene_with("{polygon: [[0.0, 0.0], [0.04, 0.0], [0.0, 0.02]], tags: [a, b]}", "[a]"));
  CHECK(tags.find("structures[0].region.tags: 2 tags for 3 polygon edges") != std::string::npos);
  const std::string unknown = error_of(
      scene_with("{polygon: [[0.0, 0.0], [0.04, 0.0], [0.0, 0.02]], tags: [a, b, c]}", "[left]"));
  CHECK(unknown.find("structures[0].interface: no region edge is tagged 'left'") !=
        std::string::npos);
}
