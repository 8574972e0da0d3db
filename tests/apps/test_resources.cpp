// Resource limits: the memory estimate of a scene, and scenes too large for the machine refused
// up front (exit status 2, the estimate in the one-line message) by the real executable.
#include "fsi/core/error.hpp"
#include "fsi_app/resources.hpp"
#include "fsi_app/scene.hpp"

#include <catch2/catch.hpp>
#include <cstdio>
#include <sys/wait.h>

using Catch::Matchers::Matches;
using fsi::app::estimate_memory;
using fsi::app::load_scene;

namespace {

struct Outcome {
  int status;
  std::string output;
};

// Runs the fsi executable with `args`; stdout and stderr together.
Outcome run_fsi(const std::string& args) {
  const std::string command = FSI_BINARY_DIR "/apps/fsi " + args + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  REQUIRE(pipe);
  std::string output;
  char buffer[512];
  while (std::fgets(buffer, sizeof buffer, pipe)) output += buffer;
  const int status = pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
}

} // namespace

TEST_CASE("apps: memory estimate counts region area / l0^2 particles", "[apps][resources]") {
  // Dam break: 0.146 m x 0.292 m of water at l0 = 1.46 mm is 100 x 200 = 20,000 particles.
  const auto scene = load_scene(FSI_SOURCE_DIR "/data/scenes/dam_break_elastic_obstacle.yaml", {});
  const auto e = estimate_memory(scene);
  CHECK(e.fluid.count == Approx(20000).epsilon(1e-9));
  // Halving l0 quadruples the particles and (the cell grid aside) the fluid memory.
  const auto fine = estimate_memory(load_scene(
      FSI_SOURCE_DIR "/data/scenes/dam_break_elastic_obstacle.yaml", {"fluid.l0=7.3e-4"}));
  CHECK(fine.fluid.count == Approx(80000).epsilon(1e-9));
  CHECK(fine.fluid.bytes / e.fluid.bytes == Approx(4.0).epsilon(0.05));
  // 2 elements_x elements_y T6 elements (2 x 12 cells here).
  REQUIRE(e.structures.size() == 1);
  CHECK(e.structures[0].count == 48);
  CHECK(fsi::app::available_memory() > 0.0);
}

TEST_CASE("apps: a fluid too large for the machine is refused with the estimate, exit 2",
          "[apps][resources]") {
  const std::string scene = FSI_TEST_DATA "/huge_fluid.yaml";
  const Outcome r = run_fsi("check " + scene);
  CHECK(r.status == 2);
  CHECK_THAT(r.output, Matches(".*/huge_fluid\\.yaml:11: fluid\\.l0: 1e\\+12 particles \\(fluid "
                               "region area / l0\\^2\\) and .* cells: the scene needs "
                               "about [0-9.e+]+ GiB, the machine has [0-9.]+ GiB available\n"));
  // The same through --set: the message names the override.
  const Outcome o =
      run_fsi("check " FSI_SOURCE_DIR "/data/scenes/hydrostatic_tank.yaml --set fluid.l0=1e-6");
  CHECK(o.status == 2);
  CHECK_THAT(o.output,
             Matches(".*hydrostatic_tank\\.yaml: --set fluid\\.l0=1e-6: fluid\\.l0: "
                     "5e\\+11 particles .*: the scene needs about [0-9.e+]+ GiB, the machine has "
                     "[0-9.]+ GiB available\n"));
}

TEST_CASE("apps: a fluid domain too large for the cell grid is refused, exit 2",
          "[apps][resources]") {
  const Outcome r = run_fsi("check " FSI_SOURCE_DIR "/data/scenes/dam_break_elastic_obstacle.yaml"
                            " --set fluid.domain.max=[1e6,1e6]");
  CHECK(r.status == 2);
  CHECK_THAT(
      r.output,
      Matches(".*/dam_break_elastic_obstacle\\.yaml: --set fluid\\.domain\\.max=\\[1e6,1e6\\]: "
              "fluid\\.domain: 2e\\+04 particles .* and 3\\.69e\\+16 cells: the scene needs "
              ".*\n"));
}

TEST_CASE("apps: an absurd FE mesh is refused with the estimate, exit 2", "[apps][resources]") {
  const Outcome r = run_fsi("check " FSI_TEST_DATA "/huge_mesh.yaml");
  CHECK(r.status == 2);
  CHECK_THAT(r.output, Matches(".*/huge_mesh\\.yaml:10: structures\\[0\\]\\.mesh: 2e\\+08 T6 "
                               "elements \\(2 elements_x elements_y\\): the scene needs about "
                               "[0-9.e+]+ GiB, the machine has [0-9.]+ GiB "
                               "available\n"));
}
