// Issue 41 item 2: a particle fluid that empties, or loses more than kMaxStepLoss of its
// particles in one step, stops the run (exit 3, run.json "failed") instead of completing.
#include "fsi/core/error.hpp"
#include "fsi_app/cli.hpp"
#include "fsi_app/particle_guard.hpp"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace fsi::app;

TEST_CASE("apps: the particle-loss guard stops at an empty fluid and at a loss above 25 %",
          "[apps][guards]") {
  const std::pair<fsi::Vec2, fsi::Vec2> box{{0.0, 0.0}, {1.0, 2.0}};
  CHECK_NOTHROW(check_particle_loss({100, box}, {75, box}, 7, 0.5, 0.75));
  CHECK_THROWS_WITH(check_particle_loss({100, box}, {74, box}, 7, 0.5, 0.75),
                    "fluid: 26 of 100 particles left the domain [(0, 0), (1, 2)] m in step 7, t = "
                    "0.5 -> 0.75 s: more than 25 % in one step (check gravity, time.courant and "
                    "fluid.domain)");
  CHECK_THROWS_WITH(check_particle_loss({1, box}, {0, box}, 1, 0.0, 0.1),
                    Catch::Contains("1 of 1 particles") && Catch::Contains("the fluid is empty"));
  CHECK_THROWS_AS(check_particle_loss({0, box}, {0, box}, 1, 0.0, 0.1), fsi::RunError);
  // A 3-D fluid's message names its three extents.
  const std::pair<Eigen::VectorXd, Eigen::VectorXd> box3{Eigen::Vector3d(0.0, 0.0, 0.0),
                                                         Eigen::Vector3d(1.0, 2.0, 3.0)};
  CHECK_THROWS_WITH(check_particle_loss({10, box3}, {0, box3}, 2, 0.0, 0.1),
                    Catch::Contains("10 of 10 particles left the domain [(0, 0, 0), (1, 2, 3)] m"));
}

TEST_CASE("apps: a fluid blown out of its domain stops the run with exit 3, either fluid",
          "[apps][guards]") {
  // EMPS: gravity -1e9 takes the 300 particles out in the first step. SPH: no wall holds the
  // column, and a domain just below it takes the particles one row after another.
  const std::string data = FSI_TEST_DATA "/";
  for (const auto& [file, overrides, what] :
       {std::tuple<std::string, std::vector<std::string>, std::string>{
            "tiny_fluid.yaml", {"gravity=[0, -1e9]"}, "300 of 300 particles left the domain"},
        {"sph_column.yaml",
         {"walls=[]", "fluid.domain={min: [-0.1, 0.0], max: [0.2, 0.2]}", "gravity=[0, -1e4]"},
         "particles left the domain"}}) {
    INFO(file);
    const auto out = std::filesystem::temp_directory_path() / ("fsi_test_particle_guard_" + file);
    std::filesystem::remove_all(out);
    std::vector<std::string> args{"run", data + file, "--out", out.string()};
    for (const auto& o : overrides) args.insert(args.end(), {"--set", o});
    std::ostringstream log, err;
    CHECK(run_cli(args, log, err, false) == 3);
    CHECK(err.str().find(what) != std::string::npos);
    std::ifstream json(out / "run.json");
    std::stringstream text;
    text << json.rdbuf();
    CHECK(text.str().find("\"status\": \"failed\"") != std::string::npos);
  }
}
