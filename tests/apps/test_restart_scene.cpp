// Issue 41 item 3: a restart of an edited scene file is refused; time.end may change (in the
// file or by --set), as extending a run needs.
#include "fsi_app/cli.hpp"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace fsi::app;

namespace {

std::string read(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

} // namespace

TEST_CASE("apps: a restart refuses an edited scene and accepts a new time.end", "[apps][restart]") {
  const auto dir = std::filesystem::temp_directory_path() / "fsi_test_restart_scene";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string original =
      read(FSI_TEST_DATA "/valid_structure.yaml") + "checkpoint:\n  interval_steps: 5\n";
  const auto scene = dir / "s.yaml";
  std::ofstream(scene) << original;
  std::ostringstream out, err;
  REQUIRE(run_cli({"run", scene.string(), "--out", (dir / "out").string()}, out, err, false) == 0);
  const std::string checkpoint = (dir / "out" / "checkpoint_000000005.h5").string();
  auto restart = [&](const std::string& text) {
    std::ofstream(scene) << text;
    std::ostringstream o, e;
    const int status =
        run_cli({"run", scene.string(), "--out", (dir / "out").string(), "--restart", checkpoint},
                o, e, false);
    return std::make_pair(status, e.str());
  };
  const auto [edited, message] = restart(replaced(original, "density: 1200.0", "density: 1300.0"));
  CHECK(edited == 2);
  CHECK(message == checkpoint + ": written for another version of " + scene.string() +
                       ": the scene was edited since (a restart may change time.end only, in "
                       "the file or by --set); restore the scene, or start a new run\n");
  CHECK(restart(original + "# a comment changes nothing\n").first == 0);
  // Last: the run to 0.02 s prunes checkpoint 5 (keep: 2).
  CHECK(restart(replaced(original, "end: 0.01", "end: 0.02")).first == 0);
}
