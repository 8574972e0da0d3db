// Issue 41 item 7: a wall motion whose period makes it non-finite is refused by its range, and
// the run's finite-value guard covers walls and structure nodes as well as particles.
#include "fsi_app/cli.hpp"
#include "fsi_app/finite_guard.hpp"
#include "test_data.hpp"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

using namespace fsi::app;

TEST_CASE("apps: a sinusoid period that makes the motion non-finite is refused", "[apps][guards]") {
  std::ostringstream out, err;
  const std::string scene = test::data_dir + "tiny_fluid.yaml";
  CHECK(run_cli({"check", scene, "--set", "walls[2].motion.period=5e-324"}, out, err, false) == 2);
  CHECK(err.str() == scene + ": --set walls[2].motion.period=5e-324: walls[2].motion.period: "
                             "4.94066e-324 s with amplitude 0.05: the motion's acceleration "
                             "amplitude * (2 pi / period)^2 is not finite; give a longer period\n");
}

TEST_CASE("apps: the finite-value guard names a point with a non-finite position or velocity",
          "[apps][guards]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CHECK_FALSE(non_finite_point("wall 'w' node 0", {1.0, 2.0}, {0.0, 0.0}));
  CHECK(non_finite_point("structure 'b' node 3", {1.0, 2.0}, {nan, 0.0}) ==
        "structure 'b' node 3 at (1, 2) m, velocity (nan, 0) m/s is not finite");
  CHECK(non_finite_point("wall 'w' node 0", {1.0, INFINITY}, {0.0, 0.0}).has_value());
}

TEST_CASE("apps: a wall gone non-finite stops the run with exit 3 naming the wall",
          "[apps][guards]") {
  // A table motion scaled to overflow (scale 1e308 on 10 rad) turns the paddle into NaN; the
  // particles never meet it, so only the wall guard sees it (before: exit 0, "completed").
  const auto dir = std::filesystem::temp_directory_path() / "fsi_test_finite_guard";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "t.csv") << "time,value\n0,0\n1,10\n";
  std::ostringstream out, err;
  CHECK(
      run_cli(
          {"run", test::data_dir + "tiny_fluid.yaml", "--out", (dir / "out").string(), "--set",
           "walls[2].motion={kind: table, table: " + (dir / "t.csv").string() + ", scale: 1e308}"},
          out, err, false) == 3);
  CHECK(err.str().find("run stopped: wall 'paddle' node 4 at (") != std::string::npos);
  CHECK(err.str().find("is not finite after step 1, t = ") != std::string::npos);
  std::ifstream json(dir / "out" / "run.json");
  std::stringstream text;
  text << json.rdbuf();
  CHECK(text.str().find("\"status\": \"failed\"") != std::string::npos);
}
