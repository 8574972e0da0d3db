// Issue 41 items 6, 8 and 10: names that collide with the output (a probe named `time`, a
// structure named `particles` or holding a path character) and fluid probe points outside the
// fluid's domain are input errors of `fsi check`, naming the key.
#include "fsi_app/cli.hpp"
#include "test_data.hpp"

#include <catch2/catch.hpp>
#include <sstream>

using namespace fsi::app;

namespace {

/// `fsi check FILE --set OVERRIDE`: the exit status and stderr.
std::pair<int, std::string> check(const std::string& file, const std::string& override) {
  std::ostringstream out, err;
  const int status = run_cli({"check", file, "--set", override}, out, err, false);
  return {status, err.str()};
}

} // namespace

TEST_CASE("apps: a probe named time is refused naming the key", "[apps][scene][names]") {
  const std::string scene = test::data_dir + "tiny_fluid.yaml";
  const auto [status, err] = check(scene, "output.probes[1].name=time");
  CHECK(status == 2);
  CHECK(err == scene + ": --set output.probes[1].name=time: output.probes[1].name: 'time' is "
                       "reserved (the first column of probes.csv); name the probe otherwise\n");
}

TEST_CASE("apps: structure names that are output groups or paths are refused",
          "[apps][scene][names]") {
  const std::string scene = test::data_dir + "valid_structure.yaml";
  for (const std::string name : {"a/b", "a.b", "a b", "..", "x\\\\y"}) {
    INFO(name);
    const auto [status, err] = check(scene, "structures[0].name=" + name);
    CHECK(status == 2);
    CHECK(err.find(": structures[0].name: '") != std::string::npos);
    CHECK(err.find("' is not a valid name (letters, digits, _ and -: it names output groups)") !=
          std::string::npos);
  }
  const auto [status, err] = check(scene, "structures[0].name=particles");
  CHECK(status == 2);
  CHECK(err == scene + ": --set structures[0].name=particles: structures[0].name: 'particles' is "
                       "reserved (the fluid's grid in fields.h5); name the structure otherwise\n");
}

TEST_CASE("apps: a fluid probe point outside the fluid domain is refused, for either fluid",
          "[apps][scene][names]") {
  // The pressure probe of each: probes[1] of the EMPS scene, probes[0] of the SPH one.
  for (const auto& [file, probe] :
       {std::pair<std::string, std::string>{"tiny_fluid.yaml", "1"}, {"sph_column.yaml", "0"}}) {
    INFO(file);
    const std::string scene = test::data_dir + file, key = "output.probes[" + probe + "].point";
    const auto [status, err] = check(scene, key + "=[1e308, 1e308]");
    CHECK(status == 2);
    CHECK(err == scene + ": --set " + key + "=[1e308, 1e308]: " + key +
                     ": the point is outside the fluid domain\n");
  }
}

TEST_CASE("apps: a fluid region outside fluid.domain is refused, for either fluid",
          "[apps][scene][names]") {
  for (const std::string type : {"emps", "sph"}) {
    INFO(type);
    const std::string scene =
        test::data_dir + (type == "emps" ? "tiny_fluid.yaml" : "sph_column.yaml");
    const auto [status, err] = check(scene, "fluid.domain={min: [1, 1], max: [2, 2]}");
    CHECK(status == 2);
    CHECK(err == scene + ": --set fluid.domain={min: [1, 1], max: [2, 2]}: fluid.domain: fluid "
                         "region 0 reaches outside the domain\n");
  }
}

TEST_CASE("apps: more frames than a run may write are refused before step 0",
          "[apps][scene][names]") {
  // Issue 41 item 5: output.interval 1e-12 s with Courant stepping filled the disk for ever.
  const std::string scene = test::data_dir + "tiny_fluid.yaml";
  const auto [status, err] = check(scene, "output.interval=1e-12");
  CHECK(status == 2);
  CHECK(err == scene + ": --set output.interval=1e-12: output.interval: time.end / "
                       "output.interval = 2e+10 frames; a run writes at most 1e+05 (give a larger "
                       "interval)\n");
  CHECK(check(scene, "output.interval=2e-7").first == 0); // exactly 1e5 frames
}
