// Issue 41 items 1 and 9: `--set` changes exactly the node it names, whatever YAML aliases share
// it (every path: through an aliased map, an aliased list entry, onto an aliased scalar), and a
// value holding a second YAML document is refused.
#include "fem/fem_spec.hpp"
#include "fsi/core/error.hpp"
#include "fsi_app/scene.hpp"

#include <catch2/catch.hpp>

using namespace fsi::app;

namespace {

// Two beams sharing one material (&m), one mesh (&r) and one clamped list; two probes sharing
// their point's y through the scalar anchor &y.
const std::string scene = R"(gravity: [0.0, -10.0]
time: {end: 0.01, dt: 1.0e-3}
output:
  interval: 0.005
  probes:
    - {name: a, quantity: displacement_y, structure: b0, point: [1.0, &y 0.1]}
    - {name: b, quantity: displacement_y, structure: b1, point: [1.0, *y]}
structures:
  - name: b0
    mesh: &r {kind: rectangle, width: 1.0, height: 0.1, elements_x: 4, elements_y: 1}
    material: &m {youngs_modulus: 2.0e6, poisson_ratio: 0.25, density: 1200.0}
    clamped: &c [left]
  - name: b1
    mesh: *r
    material: *m
    clamped: *c
)";

const fem_plugin::StructureSpec& beam(const Scene& s, std::size_t i) {
  return s.structures[i].as<fem_plugin::StructureSpec>();
}

} // namespace

TEST_CASE("apps: an override through a YAML alias changes only the node it names",
          "[apps][scene][overrides]") {
  SECTION("a key inside an aliased map") {
    const Scene s = parse_scene(scene, "s.yaml", {"structures[1].material.density=12000"});
    CHECK(beam(s, 0).options.material.density == 1200.0);
    CHECK(beam(s, 1).options.material.density == 12000.0);
  }
  SECTION("the aliased map itself") {
    const Scene s = parse_scene(scene, "s.yaml",
                                {"structures[0].mesh={kind: rectangle, width: "
                                 "2.0, height: 0.1, elements_x: 8, "
                                 "elements_y: 1}"});
    CHECK(beam(s, 0).mesh.width == 2.0);
    CHECK(beam(s, 1).mesh.width == 1.0);
  }
  SECTION("an entry of an aliased list") {
    const Scene s = parse_scene(scene, "s.yaml", {"structures[1].clamped[0]=right"});
    CHECK(beam(s, 0).clamped == std::vector<std::string>{"left"});
    CHECK(beam(s, 1).clamped == std::vector<std::string>{"right"});
  }
  SECTION("an aliased scalar") {
    const Scene s = parse_scene(scene, "s.yaml", {"output.probes[1].point[1]=0.0"});
    CHECK(s.output.probes[0].point->y() == 0.1);
    CHECK(s.output.probes[1].point->y() == 0.0);
  }
  SECTION("two overrides, one per user, and the order of the keys kept") {
    const Scene s = parse_scene(
        scene, "s.yaml",
        {"structures[0].material.density=900", "structures[1].material.poisson_ratio=0.3"});
    CHECK(beam(s, 0).options.material.density == 900.0);
    CHECK(beam(s, 0).options.material.poisson_ratio == 0.25);
    CHECK(beam(s, 1).options.material.density == 1200.0);
    CHECK(beam(s, 1).options.material.poisson_ratio == 0.3);
    CHECK(s.structures[0].name == "b0");
    CHECK(s.structures[1].name == "b1");
  }
}

TEST_CASE("apps: an override through an alias keeps the lines of the scene file",
          "[apps][scene][overrides]") {
  // The copy an override makes on its way comes from the file: a later error names its line.
  CHECK_THROWS_WITH(
      parse_scene(scene + "    stray: 1\n", "s.yaml", {"structures[1].material.density=900"}),
      Catch::StartsWith("s.yaml:17: structures[1].stray: unknown key"));
}

TEST_CASE("apps: an override value holding a second YAML document is refused",
          "[apps][scene][overrides]") {
  CHECK_THROWS_WITH(parse_scene(scene, "s.yaml", {"time.end=0.005\n---\n7"}),
                    "s.yaml: --set time.end=0.005\\n---\\n7: time.end: the value holds a "
                    "second YAML document (a '---' line); give one value");
}
