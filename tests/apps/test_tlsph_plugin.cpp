// structures[].type: tlsph regions: a rectangle (min, max), a counter-clockwise polygon with a
// tag per edge or a Gmsh mesh (issue 19: "rectangles and polygons; a Gmsh surface mesh may also
// seed them"). The polygon and mesh forms of a rectangle build the same solid; a trapezoid holds
// exactly the lattice points inside it and its interface lies on the tagged edge, given as a
// polygon or as a mesh; a clockwise polygon, a tag count that does not fit and an unknown
// interface tag are one-line errors naming the key (the bad meshes: test_scene.cpp). Probes: the
// nearest particle, or the kernel interpolation (interpolate: true), exact for a linear field.
#include "fsi/core/error.hpp"
#include "fsi_app/run.hpp"
#include "fsi_app/scene.hpp"
#include "scene_error.hpp"
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

const std::string mesh_dir = FSI_TEST_DATA "/tlsph_mesh/";

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
  const std::string clockwise = test::scene_text_error(
      scene_with("{polygon: [[0.0, 0.0], [0.0, 0.02], [0.04, 0.02], [0.04, 0.0]]}", "[boundary]"));
  CHECK(clockwise.find("scene.yaml:") == 0);
  CHECK(clockwise.find("structures[0].region.polygon: must be counter-clockwise") !=
        std::string::npos);
  const std::string tags = test::scene_text_error(
      scene_with("{polygon: [[0.0, 0.0], [0.04, 0.0], [0.0, 0.02]], tags: [a, b]}", "[a]"));
  CHECK(tags.find("structures[0].region.tags: 2 tags for 3 polygon edges") != std::string::npos);
  const std::string unknown = test::scene_text_error(
      scene_with("{polygon: [[0.0, 0.0], [0.04, 0.0], [0.0, 0.02]], tags: [a, b, c]}", "[left]"));
  CHECK(unknown.find("structures[0].interface: no region edge is tagged 'left'") !=
        std::string::npos);
}

TEST_CASE("tlsph plug-in: a rectangle as a Gmsh mesh builds the same solid", "[apps][tlsph]") {
  const Scene box = parse_scene(scene_with("{min: [0.0, 0.0], max: [0.02, 0.04]}", "[left, top]"),
                                "scene.yaml", {});
  const Scene mesh = parse_scene(scene_with("{file: " + mesh_dir + "rectangle.msh}", "[left, top]"),
                                 "scene.yaml", {});
  using tlsph_plugin::TlsphSpec;
  const TlsphSpec &ta = box.structures.front().as<TlsphSpec>(),
                  &tb = mesh.structures.front().as<TlsphSpec>();
  CHECK(tb.outline == ta.outline); // the 4 corners from (0, 0), counter-clockwise
  CHECK(tb.tags == ta.tags);       // bottom, right, top, left: the mesh's physical groups
  TlsphModel a(box, box.structures.front()), b(mesh, mesh.structures.front());
  REQUIRE(b.solid().size() == a.solid().size());
  CHECK(a.solid().size() == 200);
  double dx = 0.0;
  for (std::size_t i = 0; i < a.solid().size(); ++i)
    dx = std::max(dx, (b.solid().reference_position(i) - a.solid().reference_position(i)).norm());
  CHECK(dx == 0.0);
  REQUIRE(b.interface_mesh().node_count() == a.interface_mesh().node_count());
  CHECK(b.interface_mesh().X0 == a.interface_mesh().X0);
  CHECK(b.solid().interface_particles() == a.solid().interface_particles());
}

TEST_CASE("tlsph plug-in: a trapezoid mesh holds the particles of its polygon twin",
          "[apps][tlsph]") {
  // trapezoid.msh (msh 2.2): the polygon below, 4 x 5 elements along its sides, the left side in
  // no physical group. Its slope's mid-nodes are gmsh's (collinear to ~1e-14).
  const Scene polygon = parse_scene(
      scene_with("{polygon: [[0.0, 0.0], [0.04, 0.0], [0.03, 0.02], [0.0, 0.02]], tags: "
                 "[bottom, slope, top, boundary]}",
                 "[slope]"),
      "scene.yaml", {});
  const Scene mesh =
      parse_scene(scene_with("{file: " + mesh_dir + "trapezoid.msh}", "[slope]"), "scene.yaml", {});
  const auto& spec = mesh.structures.front().as<tlsph_plugin::TlsphSpec>();
  CHECK(spec.outline == polygon.structures.front().as<tlsph_plugin::TlsphSpec>().outline);
  CHECK(spec.tags == std::vector<std::string>{"bottom", "slope", "top", "boundary"});
  TlsphModel a(polygon, polygon.structures.front()), b(mesh, mesh.structures.front());
  CHECK(a.solid().size() == 175); // the lattice points with (i + 1/2) dp < 0.04 - (j + 1/2) dp / 2
  REQUIRE(b.solid().size() == a.solid().size());
  double dx = 0.0;
  for (std::size_t i = 0; i < a.solid().size(); ++i)
    dx = std::max(dx, (b.solid().reference_position(i) - a.solid().reference_position(i)).norm());
  CHECK(dx == 0.0);
  CHECK(b.interface_mesh().X0 == a.interface_mesh().X0);
}

TEST_CASE("tlsph plug-in: an interpolating probe is exact for a linear field, the nearest "
          "particle's is not",
          "[apps][tlsph]") {
  const std::string probes =
      "output:\n  interval: 0.001\n  probes:\n"
      "    - {name: nearest, quantity: displacement_x, structure: block, point: [0.0123, 0.0311]}\n"
      "    - {name: kernel, quantity: displacement_x, structure: block, point: [0.0123, 0.0311], "
      "interpolate: true}\n"
      "    - {name: corner, quantity: displacement_y, structure: block, point: [0.02, 0.04], "
      "interpolate: true}\n";
  std::string text = scene_with("{min: [0.0, 0.0], max: [0.02, 0.04]}", "[top]");
  text.replace(text.find("output: {interval: 0.001}\n"), 26, probes);
  const Scene scene = parse_scene(text, "scene.yaml", {});
  TlsphModel model(scene, scene.structures.front());
  fsi::Mat2 A;
  A << 0.013, -0.021, 0.007, 0.017;
  const Vec2 c(1e-3, -2e-3);
  std::vector<Vec2> x(model.solid().size());
  for (std::size_t i = 0; i < x.size(); ++i)
    x[i] = model.solid().reference_position(i) + A * model.solid().reference_position(i) + c;
  model.solid().set_positions(x);
  const auto& p = scene.output.probes;
  const Vec2 X = *p[0].point, corner = *p[2].point;
  const double exact = (A * X + c).x();
  const double nearest = std::abs(*model.probe(p[0]) - exact);
  const double kernel = std::abs(*model.probe(p[1]) - exact);
  const double at_corner = std::abs(*model.probe(p[2]) - (A * corner + c).y());
  INFO("nearest " << nearest << ", kernel " << kernel << ", corner " << at_corner);
  // |u| ~ 1e-3: round-off (measured 3.3e-19 and 4.3e-18); the corner lies dp / 2 beyond the
  // last particles in x and y (an extrapolation).
  CHECK(kernel < 1e-15);
  CHECK(at_corner < 1e-15);
  CHECK(nearest > 1e-5); // the particle (0.013, 0.031): [A (X_p - X)]_x = 1.12e-5
}

TEST_CASE("tlsph plug-in: interpolate is refused where it has no meaning", "[apps][tlsph]") {
  std::string text = scene_with("{min: [0.0, 0.0], max: [0.02, 0.04]}", "[top]");
  text.replace(text.find("output: {interval: 0.001}\n"), 26,
               "output:\n  interval: 0.001\n  probes:\n    - {name: far, quantity: "
               "displacement_x, structure: block, point: [0.1, 0.1], interpolate: true}\n");
  const Scene scene = parse_scene(text, "scene.yaml", {});
  std::string off;
  try {
    TlsphModel model(scene, scene.structures.front());
  } catch (const InputError& e) {
    off = e.what();
  }
  CHECK(off == "scene.yaml:6: output.probes[0].point: tlsph: probe point (0.1, 0.1) is off the "
               "solid: its 0 particles within 2h do not span the plane");
  // A fluid quantity does not interpolate; an FE probe reads its node either way (the FE
  // interpolation at a node: a scene's probes hold for either structure type).
  text.replace(text.find("displacement_x, structure: block,"), 33, "mean_speed,");
  CHECK(test::scene_text_error(text).find(
            "scene.yaml:6: output.probes[0].interpolate: only a structure's "
            "displacement probes interpolate") == 0);
  const std::string fem = FSI_TEST_DATA "/valid_structure.yaml";
  const Scene nodal = load_scene(fem, {}),
              interpolated = load_scene(fem, {"output.probes[0].interpolate=true"});
  const auto a = build_models(nodal), b = build_models(interpolated);
  a.front()->advance(0.0, *nodal.time.dt), b.front()->advance(0.0, *interpolated.time.dt);
  CHECK(*a.front()->probe(nodal.output.probes[0]) < 0.0); // the tip sags after one step
  CHECK(*b.front()->probe(interpolated.output.probes[0]) ==
        *a.front()->probe(nodal.output.probes[0]));
}

TEST_CASE("tlsph plug-in: a tank-frame probe undoes its clamp wall's rigid motion",
          "[apps][tlsph]") {
  // The wall turned by theta = 0.3 rad about p at t = 0 (phase pi/2); the solid set to that
  // rotation of X + A X + c: in the tank's frame the displacement is A X + c, exactly.
  const std::string probes =
      "walls:\n  - name: tank\n    polyline: [[-1.0, 1.0], [-1.0, -1.0], [1.0, -1.0], [1.0, 1.0]]\n"
      "    motion: {kind: sinusoid, dof: rotation, pivot: [0.01, -0.02], amplitude: 0.3, "
      "period: 1.0, phase: 1.5707963267948966}\n"
      "output:\n  interval: 0.001\n  probes:\n"
      "    - {name: tx, quantity: displacement_x_tank, structure: block, point: [0.0123, 0.0311], "
      "interpolate: true}\n"
      "    - {name: ty, quantity: displacement_y_tank, structure: block, point: [0.0123, 0.0311], "
      "interpolate: true}\n"
      "    - {name: x, quantity: displacement_x, structure: block, point: [0.0123, 0.0311], "
      "interpolate: true}\n";
  std::string text = scene_with("{min: [0.0, 0.0], max: [0.02, 0.04]}", "[top]") +
                     "    clamped_motion: tank\n    clamped: [{min: [0.0, 0.0], max: [0.02, "
                     "0.004]}]\n";
  text.replace(text.find("output: {interval: 0.001}\n"), 26, probes);
  const Scene scene = parse_scene(text, "scene.yaml", {});
  TlsphModel model(scene, scene.structures.front());
  fsi::Mat2 A, R;
  A << 0.013, -0.021, 0.007, 0.017;
  R << std::cos(0.3), -std::sin(0.3), std::sin(0.3), std::cos(0.3);
  const Vec2 c(1e-3, -2e-3), p(0.01, -0.02);
  std::vector<Vec2> x(model.solid().size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    const Vec2 X = model.solid().reference_position(i);
    x[i] = p + R * (X + A * X + c - p);
  }
  model.solid().set_positions(x);
  const auto& pr = scene.output.probes;
  const Vec2 X = *pr[0].point, u_tank = A * X + c, u_lab = p + R * (X + u_tank - p) - X;
  INFO("tank " << *model.probe(pr[0]) << ", " << *model.probe(pr[1]) << "; lab "
               << *model.probe(pr[2]));
  CHECK(std::abs(*model.probe(pr[0]) - u_tank.x()) < 1e-15);
  CHECK(std::abs(*model.probe(pr[1]) - u_tank.y()) < 1e-15);
  CHECK(std::abs(*model.probe(pr[2]) - u_lab.x()) < 1e-15);
  CHECK(std::abs(u_lab.x() - u_tank.x()) > 1e-3); // the rotation moves the point by mm
}

TEST_CASE("tlsph plug-in: a tank-frame probe needs a clamped_motion", "[apps][tlsph]") {
  std::string text = scene_with("{min: [0.0, 0.0], max: [0.02, 0.04]}", "[top]");
  text.replace(text.find("output: {interval: 0.001}\n"), 26,
               "output:\n  interval: 0.001\n  probes:\n    - {name: tx, quantity: "
               "displacement_x_tank, structure: block, point: [0.01, 0.03]}\n");
  CHECK(test::scene_text_error(text) ==
        "scene.yaml:6: output.probes[0].quantity: 'displacement_x_tank' needs "
        "structure 'block' to have a clamped_motion");
}
