// A structure-only run end to end: the probes in probes.csv are the FE solution at the probed
// node, frame by frame, and fields.h5, probes.csv and run.json agree on what was written.
#include "fem/fem_model.hpp"
#include "fsi_app/cli.hpp"
#include "fsi_app/output/fields_file.hpp"
#include "fsi_app/scene.hpp"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

using namespace fsi::app;
namespace fs = std::filesystem;

namespace {
std::vector<std::vector<double>> read_csv(const fs::path& file, std::string& header) {
  std::ifstream in(file);
  std::getline(in, header);
  std::vector<std::vector<double>> rows;
  for (std::string line; std::getline(in, line);) {
    std::vector<double> row;
    std::stringstream fields(line);
    for (std::string v; std::getline(fields, v, ',');) row.push_back(std::stod(v));
    rows.push_back(row);
  }
  return rows;
}
} // namespace

TEST_CASE("apps: a structure-only run writes the FE solution at the probed node", "[apps][run]") {
  const std::string scene_file = FSI_TEST_DATA "/valid_structure.yaml";
  const fs::path out = fs::temp_directory_path() / "fsi_test_run";
  fs::remove_all(out);
  std::ostringstream sout, serr;
  REQUIRE(run_cli({"run", scene_file, "--out", out.string(), "--set", "time.end=0.02"}, sout, serr,
                  false) == 0);

  std::string header;
  const auto rows = read_csv(out / "probes.csv", header);
  CHECK(header == "time,tip");
  REQUIRE(rows.size() == 5); // t = 0, 0.005, ..., 0.02

  // The same scene advanced directly through the library.
  const Scene scene = load_scene(scene_file, {"time.end=0.02"});
  auto structure = fem_plugin::build_structure(scene, scene.structures[0]);
  const int node = fem_plugin::probe_node(scene, structure->mesh(), scene.output.probes[0]);
  CHECK(structure->mesh().X[static_cast<std::size_t>(node)].isApprox(fsi::Vec2(1.0, 0.1)));
  for (std::size_t k = 0; k < rows.size(); ++k) {
    if (k > 0)
      for (int s = 0; s < 5; ++s) structure->advance(1e-3);
    CHECK(rows[k][0] == Approx(0.005 * static_cast<double>(k)).margin(1e-12));
    CHECK(rows[k][1] == Approx(structure->displacement()[2 * node + 1]).epsilon(1e-9));
    const auto u =
        read_dataset(out / "fields.h5", "frames/" + std::to_string(k) + "/beam/displacement");
    CHECK(u.values[static_cast<std::size_t>(2 * node + 1)] == Approx(rows[k][1]).epsilon(1e-9));
  }
  CHECK(rows.back()[1] < -1e-5); // the beam sags under gravity

  std::ifstream json(out / "run.json");
  std::stringstream text;
  text << json.rdbuf();
  CHECK(text.str().find("\"status\": \"completed\"") != std::string::npos);
  CHECK(text.str().find("\"steps\": 20") != std::string::npos);
  CHECK(text.str().find("\"frames\": 5") != std::string::npos);
  CHECK(text.str().find("\"elements\": 8") != std::string::npos);
}

TEST_CASE("apps: a boundary tag the mesh lacks is refused before the run", "[apps][run]") {
  std::ostringstream out, err;
  const int status = run_cli(
      {"check", FSI_TEST_DATA "/valid_structure.yaml", "--set", "structures[0].clamped=[nowhere]"},
      out, err, false);
  CHECK(status == 2);
  CHECK(err.str().find("structures[0].clamped: unknown boundary tag 'nowhere'") !=
        std::string::npos);
}

TEST_CASE("apps: every shipped scene passes fsi check", "[apps][run]") {
  int scenes = 0;
  for (const auto& entry : fs::directory_iterator(FSI_SOURCE_DIR "/data/scenes")) {
    if (entry.path().extension() != ".yaml") continue;
    std::ostringstream out, err;
    INFO(entry.path());
    CHECK(run_cli({"check", entry.path().string()}, out, err, false) == 0);
    CHECK(err.str().empty());
    ++scenes;
  }
  CHECK(scenes >= 3);
}

TEST_CASE("apps: a fluid run writes its particles, the surge front and its counts", "[apps][run]") {
  const fs::path out = fs::temp_directory_path() / "fsi_test_fluid_run";
  fs::remove_all(out);
  std::ostringstream sout, serr;
  // The shipped dam break, coarsened and shortened.
  REQUIRE(run_cli({"run", FSI_SOURCE_DIR "/data/scenes/dam_break_rigid.yaml", "--out", out.string(),
                   "--set", "fluid.l0=0.01", "--set", "time.end=0.02"},
                  sout, serr, false) == 0);
  const auto x0 = read_dataset(out / "fields.h5", "frames/0/particles/position");
  CHECK(x0.dims == std::vector<std::size_t>{200, 2}); // a 0.1 x 0.2 m column at l0 = 0.01 m
  const auto p = read_dataset(out / "fields.h5", "frames/4/particles/pressure");
  CHECK(*std::max_element(p.values.begin(), p.values.end()) > 500.0); // the column weighs
  std::string header;
  const auto rows = read_csv(out / "probes.csv", header);
  CHECK(header == "time,front");
  REQUIRE(rows.size() == 5);
  CHECK_THAT(rows.front()[1], Catch::Matchers::WithinAbs(0.095, 1e-9)); // last column centre
  CHECK(rows.back()[1] > rows.front()[1]);                              // the front advances
  std::ifstream json(out / "run.json");
  std::stringstream text;
  text << json.rdbuf();
  CHECK(text.str().find("\"particles_initial\": 200") != std::string::npos);
  CHECK(text.str().find("\"removed_particles\": 0") != std::string::npos);
  // The wall model as resolved: the scene's preset and its terms, set and left alone.
  CHECK(text.str().find("\"wall_model\": \"default\"") != std::string::npos);
  CHECK(text.str().find("\"wall_approach_viscosity\": 0.5") != std::string::npos);
  CHECK(text.str().find("\"mirror_same_side\": true") != std::string::npos);
  CHECK(text.str().find("\"wall_contact\": \"paper\"") != std::string::npos);
  // The fluid's list builds (at least the first, at most two a step) and its time split (six
  // parts net of the waits in collectives, and the waits), which adds up to no more than the
  // run's wall time.
  const std::string run_json = text.str();
  std::smatch m;
  REQUIRE(std::regex_search(run_json, m, std::regex("\"neighbour_list_builds\": (\\d+)")));
  const long builds = std::stol(m[1]);
  REQUIRE(std::regex_search(run_json, m, std::regex("\"steps\": (\\d+)")));
  CHECK(builds >= 1);
  CHECK(builds <= 2 * std::stol(m[1]));
  REQUIRE(std::regex_search(run_json, m, std::regex("\"seconds\": \\{([^}]*)\\}")));
  const std::string parts = m[1];
  double sum = 0;
  int count = 0;
  const std::regex number(": ([0-9.e+-]+)");
  for (std::sregex_iterator it(parts.begin(), parts.end(), number), end; it != end; ++it, ++count)
    sum += std::stod((*it)[1]);
  CHECK(count == 7);
  REQUIRE(std::regex_search(run_json, m, std::regex("\"wall_seconds\": ([0-9.e+-]+)")));
  CHECK(sum > 0);
  CHECK(sum <= std::stod(m[1]));
}

TEST_CASE("apps: a Courant-stepped run lands on its frames without a sliver of a step",
          "[apps][run]") {
  // Before issue 21's change the step before a frame was whatever was left (6.7e-6 s against a
  // stable 2e-4 s here): the last two steps now share it when it is under two steps.
  const fs::path out = fs::temp_directory_path() / "fsi_test_courant_frames";
  fs::remove_all(out);
  std::ostringstream sout, serr;
  REQUIRE(run_cli({"run", FSI_SOURCE_DIR "/data/scenes/dam_break_rigid.yaml", "--out", out.string(),
                   "--set", "fluid.l0=0.01", "--set", "time={end: 0.02, courant: 0.4}"},
                  sout, serr, false) == 0);
  std::string header;
  const auto rows = read_csv(out / "probes.csv", header);
  REQUIRE(rows.size() == 5);
  for (std::size_t k = 0; k < rows.size(); ++k)
    CHECK_THAT(rows[k][0], Catch::Matchers::WithinAbs(0.005 * static_cast<double>(k), 1e-12));
  std::ifstream json(out / "run.json");
  std::stringstream text;
  text << json.rdbuf();
  const std::string run_json = text.str();
  std::smatch lo, hi;
  REQUIRE(std::regex_search(run_json, lo, std::regex("\"dt_min\": ([0-9.e+-]+)")));
  REQUIRE(std::regex_search(run_json, hi, std::regex("\"dt_max\": ([0-9.e+-]+)")));
  INFO("dt_min " << lo[1] << ", dt_max " << hi[1]);
  CHECK(std::stod(lo[1]) >= 0.4 * std::stod(hi[1]));
}
