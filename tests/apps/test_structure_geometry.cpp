// One structure for either structure type by one override (issue 41, item 12;
// apps/solvers/structure_geometry.hpp): the FE cantilever as a TL-SPH solid (its rectangle
// filled, its clamped side continued into a clamp) and the two solvers' tip deflections; a
// TL-SPH rectangle with a clamp strip as an FE rectangle; and what does not translate, refused
// naming the key.
#include "fem/fem_spec.hpp"
#include "fsi/core/error.hpp"
#include "fsi_app/run.hpp"
#include "fsi_app/scene.hpp"
#include "scene_error.hpp"
#include "scene_probes.hpp"
#include "tlsph/tlsph_model.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <string>

using namespace fsi;
using namespace fsi::app;
using Catch::Contains;

namespace {

const std::string cantilever = FSI_SOURCE_DIR "/data/scenes/cantilever.yaml";

/// tip_y of the cantilever after each 0.01 s up to 0.35 s (the first swing's lowest point is
/// near 0.3 s), with the structure of the given type.
std::vector<double> tip_history(const std::string& type) {
  const Scene scene = load_scene(cantilever, {"structures[0].type=" + type});
  const auto models = build_models(scene);
  REQUIRE(models.size() == 1);
  const ProbeSpec& tip = test::named(scene, "tip_y");
  const double dt = *scene.time.dt;
  std::vector<double> out;
  for (int k = 0; k < 350; ++k) {
    models.front()->advance(k * dt, dt);
    if ((k + 1) % 10 == 0) out.push_back(*models.front()->probe(tip));
  }
  return out;
}

} // namespace

TEST_CASE("apps: the FE cantilever as a TL-SPH solid by one override", "[apps][tlsph]") {
  const Scene scene = load_scene(cantilever, {"structures[0].type=tlsph"});
  REQUIRE(scene.structures.front().type == "tlsph");
  tlsph_plugin::TlsphModel model(scene, scene.structures.front());
  const tlsph::TlsphSolid& solid = model.solid();
  // dp: the T6 node spacing, min(1 / 40, 0.1 / 4) = 0.025 m; the 1 x 0.1 m beam is 40 x 4
  // particles and the clamp 4 columns beyond x = 0.
  const double dp = 0.025;
  REQUIRE(solid.size() == 44 * 4);
  Vec2 lo = Vec2::Constant(1e9), hi = Vec2::Constant(-1e9);
  std::size_t clamped = 0;
  for (std::size_t i = 0; i < solid.size(); ++i) {
    const Vec2 X = solid.reference_position(i);
    if (solid.clamped(i)) { // the clamp: 4 columns beyond the FE clamped side x = 0
      ++clamped;
      CHECK(X.x() < 0.0);
      CHECK(X.x() > -4 * dp);
      continue;
    }
    CHECK(X.x() > 0.0);
    lo = lo.cwiseMin(X), hi = hi.cwiseMax(X);
  }
  CHECK(clamped == 4 * 4);
  // The free particles fill the FE rectangle [0, 1] x [0, 0.1] to within dp / 2 of its sides.
  CHECK_THAT(lo.x(), Catch::WithinAbs(0.0, dp / 2 + 1e-12));
  CHECK_THAT(lo.y(), Catch::WithinAbs(0.0, dp / 2 + 1e-12));
  CHECK_THAT(hi.x(), Catch::WithinAbs(1.0, dp / 2 + 1e-12));
  CHECK_THAT(hi.y(), Catch::WithinAbs(0.1, dp / 2 + 1e-12));
  // A dp given for the tlsph type is kept (the clamp then 4 of its rows).
  const Scene fine =
      load_scene(cantilever, {"structures[0].type=tlsph", "structures[0].tlsph.dp=0.0125"});
  tlsph_plugin::TlsphModel fine_model(fine, fine.structures.front());
  CHECK(fine_model.solid().size() == 84 * 8);
}

TEST_CASE("apps: the cantilever's tip swings alike as FE and as TL-SPH", "[apps][tlsph]") {
  // Measured (2026-12-04): the first swing's lowest tip_y, FE -0.26385 m at 0.30 s, TL-SPH at
  // the derived dp = 0.025 m -0.27684 m at 0.31 s (4.9 % deeper; at dp = 0.0125 m -0.26723 m at
  // 0.30 s, 1.3 %); at 0.2 s -0.20433 and -0.20586 m (0.75 %).
  const std::vector<double> fe = tip_history("fem"), sph = tip_history("tlsph");
  REQUIRE(fe.size() == sph.size());
  CHECK(sph[19] < 0.0); // 0.2 s: falling under its weight
  CHECK_THAT(sph[19], Catch::WithinRel(fe[19], 0.015));
  const auto lowest = [](const std::vector<double>& v) {
    return std::min_element(v.begin(), v.end()) - v.begin();
  };
  const auto k_fe = lowest(fe), k_sph = lowest(sph);
  CHECK(std::abs(k_fe - k_sph) <= 2); // within 0.02 s
  CHECK(fe[static_cast<std::size_t>(k_fe)] < -0.25);
  CHECK_THAT(sph[static_cast<std::size_t>(k_sph)],
             Catch::WithinRel(fe[static_cast<std::size_t>(k_fe)], 0.06));
}

TEST_CASE("apps: a TL-SPH rectangle with a clamp strip as an FE rectangle", "[apps][fem]") {
  // The block 0.02 x 0.04 m above a 4-row clamp strip y = -0.008 .. 0 at dp = 0.002 m.
  const std::string text =
      "name: block\ntime: {end: 0.001, dt: 1.0e-5}\noutput: {interval: 0.001}\n"
      "structures:\n  - name: block\n    type: fem\n    material: {youngs_modulus: 1.0e6, "
      "poisson_ratio: 0.3, density: 1000.0}\n    tlsph:\n      dp: 0.002\n      region: {min: "
      "[0.0, -0.008], max: [0.02, 0.04]}\n      clamped:\n        - {min: [0.0, -0.008], max: "
      "[0.02, 0.0]}\n";
  const Scene scene = parse_scene(text, "scene.yaml", {});
  const auto& fe = scene.structures.front().as<fem_plugin::StructureSpec>();
  CHECK(fe.mesh.kind == "rectangle");
  CHECK(fe.mesh.origin == Vec2(0.0, 0.0));
  CHECK_THAT(fe.mesh.width, Catch::WithinAbs(0.02, 1e-15));
  CHECK_THAT(fe.mesh.height, Catch::WithinAbs(0.04, 1e-15));
  CHECK(fe.mesh.elements_x == 5); // nodes dp apart: 0.02 / (2 dp)
  CHECK(fe.mesh.elements_y == 10);
  CHECK(fe.clamped == std::vector<std::string>{"bottom"});
  // A box that is no side's strip, and a polygon, do not translate.
  std::string off = text;
  off.replace(off.find("max: [0.02, 0.0]"), 16, "max: [0.01, 0.0]");
  CHECK_THAT(test::scene_text_error(off),
             Contains("scene.yaml:11: structures[0].tlsph.clamped: box 0 (0, -0.008) - (0.01, "
                      "0) is not the strip of one side of the region"));
  std::string polygon = text;
  polygon.replace(polygon.find("{min: [0.0, -0.008], max: [0.02, 0.04]}"), 39,
                  "{polygon: [[0.0, -0.008], [0.02, -0.008], [0.02, 0.04], [0.0, 0.04]]}");
  CHECK_THAT(test::scene_text_error(polygon),
             Contains("scene.yaml:10: structures[0].tlsph.region: a TL-SPH polygon does not "
                      "translate to an FE mesh"));
}

TEST_CASE("apps: a 3-D TL-SPH solid of a T10 box as FE: the box, its tlsph block checked as the "
          "box translates and set aside",
          "[apps][fem]") {
  // cantilever_3d_tlsph_static: type tlsph, the T10 box 20 x 2 x 2 of 1 x 0.1 x 0.1 m clamped at
  // its left, tlsph: {dp: 0.01, mass_damping: 60}.
  const std::string file = FSI_SOURCE_DIR "/data/scenes/cantilever_3d_tlsph_static.yaml";
  const Scene scene = load_scene(file, {"structures[0].type=fem"});
  const auto& fe = scene.structures.front().as<fem_plugin::StructureSpec>();
  CHECK(fe.mesh.kind == "box");
  CHECK(fe.mesh.elements_x == 20);
  CHECK(fe.mesh.elements_y == 2);
  CHECK(fe.mesh.elements_z == 2);
  CHECK(fe.clamped == std::vector<std::string>{"left"});
  // The set-aside block is still checked: a bad TL-SPH key in it is refused by name.
  CHECK_THAT(test::scene_file_error(file, {"structures[0].type=fem", "structures[0].tlsph.dp=-1"}),
             Contains("structures[0].tlsph.dp"));
}

TEST_CASE("apps: what does not translate between the structure types is refused naming the key",
          "[apps][tlsph]") {
  // Loads: TL-SPH has none.
  CHECK_THAT(test::scene_file_error(cantilever,
                                    {"structures[0].type=tlsph",
                                     "structures[0].loads=[{boundary: right, force: [0, -1]}]"}),
             Contains("structures[0].loads: a TL-SPH solid takes no constant loads"));
  // 3-D: TL-SPH has no sliding faces and fixed clamps (the slab's sides would be dropped).
  const std::string cantilever_3d = FSI_SOURCE_DIR "/data/scenes/cantilever_3d.yaml";
  CHECK_THAT(test::scene_file_error(cantilever_3d,
                                    {"structures[0].type=tlsph", "structures[0].sliding=[back]"}),
             Contains("structures[0].sliding: a TL-SPH solid has no sliding faces"));
  CHECK_THAT(
      test::scene_file_error(
          cantilever_3d, {"structures[0].type=tlsph",
                          "structures[0].clamped_rigid_motion={kind: sinusoid, axis: [0, 1, 0], "
                          "pivot: [0, 0, 0], amplitude: 0.1, period: 1}"}),
      Contains("structures[0].clamped_rigid_motion: a 3-D TL-SPH solid's clamps are fixed"));
  // A clamped tag the rectangle does not have.
  CHECK_THAT(test::scene_file_error(cantilever,
                                    {"structures[0].type=tlsph", "structures[0].clamped=[side]"}),
             Contains("structures[0].clamped: no side of the mesh is tagged 'side'"));
  // A Gmsh mesh whose clamped side is not along an axis (the trapezoid's slope).
  const std::string mesh = FSI_TEST_DATA "/tlsph_mesh/trapezoid.msh";
  const std::string text =
      "name: block\ntime: {end: 0.001, dt: 1.0e-5}\noutput: {interval: 0.001}\n"
      "structures:\n  - name: block\n    type: tlsph\n    material: {youngs_modulus: 1.0e6, "
      "poisson_ratio: 0.3, density: 1000.0}\n    mesh: {kind: gmsh, file: " +
      mesh + "}\n    clamped: [slope]\n";
  CHECK_THAT(test::scene_text_error(text),
             Contains("scene.yaml:9: structures[0].clamped: the side 'slope' from") &&
                 Contains("is not parallel to an axis"));
  // A Gmsh rectangle clamped at its bottom: 4 rows below y = 0 clamped, as many columns as the
  // free rows have.
  std::string rectangle = text;
  rectangle.replace(rectangle.find("trapezoid.msh"), 13, "rectangle.msh");
  rectangle.replace(rectangle.find("[slope]"), 7, "[bottom]");
  const Scene scene = parse_scene(rectangle, "scene.yaml", {});
  tlsph_plugin::TlsphModel model(scene, scene.structures.front());
  std::size_t clamped = 0, bottom_row = 0;
  double lowest_free = 1.0;
  for (std::size_t i = 0; i < model.solid().size(); ++i) {
    const Vec2 X = model.solid().reference_position(i);
    if (model.solid().clamped(i)) {
      ++clamped;
      CHECK(X.y() < 0.0);
    } else {
      lowest_free = std::min(lowest_free, X.y());
    }
  }
  for (std::size_t i = 0; i < model.solid().size(); ++i)
    if (!model.solid().clamped(i) && model.solid().reference_position(i).y() == lowest_free)
      ++bottom_row;
  CHECK(lowest_free > 0.0);
  CHECK(bottom_row >= 3);
  CHECK(clamped == 4 * bottom_row);
}
