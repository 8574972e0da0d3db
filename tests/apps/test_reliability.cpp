// Reliability of the `fsi` executable (docs/reliability.md), each through the real program:
// a run continued from a checkpoint is bitwise the uninterrupted run; SIGINT stops it with a
// checkpoint that restarts; after SIGKILL every frame fields.xmf names is readable; each guard
// stops the run with one message, its last state and exit status 3; output is bitwise the same
// for the same and for different thread counts.
#include "fsi_app/output/checkpoint_file.hpp"
#include "fsi_app/output/fields_file.hpp"
#include "fsi_process.hpp"

#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <hdf5.h>
#include <limits>
#include <regex>
#include <sstream>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace fs = std::filesystem;
using fsi_test::check_indexed_datasets;
using fsi_test::frames_in;
using fsi_test::slurp;
using fsi_test::wait_status;

namespace {

const std::string coupled = FSI_TEST_DATA "/tiny_coupled.yaml";
const std::string fluid = FSI_TEST_DATA "/tiny_fluid.yaml";
const std::string structure = FSI_TEST_DATA "/valid_structure.yaml";

fs::path fresh(const std::string& name) {
  return fsi_test::fresh_dir("reliability", name);
}

pid_t spawn(const std::vector<std::string>& args, const fs::path& dir) {
  return fsi_test::spawn(FSI_EXECUTABLE, args, dir);
}

/// Runs `fsi run SCENE --out DIR ARGS...` to the end; its stderr goes to DIR/../NAME.err.
int fsi_run(const std::string& scene, const fs::path& out, std::vector<std::string> args,
            std::string* err = nullptr) {
  args.insert(args.begin(), {"run", scene, "--out", out.string()});
  const fs::path logs = fresh(out.filename().string() + "_logs");
  const int status = wait_status(spawn(args, logs));
  if (err) *err = slurp(logs / "stderr.txt");
  return status;
}

std::size_t lines(const fs::path& file) {
  const std::string text = slurp(file);
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

/// Every dataset below `group` of an open HDF5 file, as paths.
void datasets(hid_t file, const std::string& group, std::vector<std::string>& out) {
  std::vector<std::string> names;
  H5Literate_by_name(
      file, group.c_str(), H5_INDEX_NAME, H5_ITER_INC, nullptr,
      [](hid_t, const char* name, const H5L_info_t*, void* data) -> herr_t {
        static_cast<std::vector<std::string>*>(data)->push_back(name);
        return 0;
      },
      &names, H5P_DEFAULT);
  for (const auto& name : names) {
    const std::string path = (group == "/" ? "" : group) + "/" + name;
    const hid_t object = H5Oopen(file, path.c_str(), H5P_DEFAULT);
    REQUIRE(object >= 0);
    if (H5Iget_type(object) == H5I_GROUP)
      datasets(file, path, out);
    else
      out.push_back(path);
    H5Oclose(object);
  }
}

std::vector<std::string> datasets(const fs::path& h5) {
  const hid_t file = H5Fopen(h5.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  REQUIRE(file >= 0);
  std::vector<std::string> out;
  datasets(file, "/", out);
  H5Fclose(file);
  return out;
}

/// fields.h5 of two runs: the same datasets, bitwise equal; and the same probes.csv text.
void require_same_output(const fs::path& a, const fs::path& b) {
  CHECK(slurp(a / "probes.csv") == slurp(b / "probes.csv"));
  CHECK(slurp(a / "fields.xmf") == slurp(b / "fields.xmf"));
  const auto names = datasets(a / "fields.h5");
  REQUIRE(names == datasets(b / "fields.h5"));
  REQUIRE(names.size() > 10);
  for (const auto& name : names) {
    const auto x = fsi::app::read_dataset(a / "fields.h5", name);
    const auto y = fsi::app::read_dataset(b / "fields.h5", name);
    INFO(name);
    REQUIRE(x.dims == y.dims);
    REQUIRE(std::memcmp(x.values.data(), y.values.data(), x.values.size() * sizeof(double)) == 0);
  }
}

/// The first `columns` columns of a CSV (coupling.csv without its wall times).
std::string columns(const fs::path& file, int count) {
  std::istringstream in(slurp(file));
  std::string out;
  for (std::string line; std::getline(in, line);) {
    std::size_t at = 0;
    for (int k = 0; k < count && at != std::string::npos; ++k) at = line.find(',', at + 1);
    out += line.substr(0, at) + '\n';
  }
  return out;
}

std::string json_text(const fs::path& run_json, const std::string& key) {
  const std::regex pattern("\"" + key + "\": \"([^\"]*)\"");
  std::smatch m;
  const std::string text = slurp(run_json);
  return std::regex_search(text, m, pattern) ? m[1].str() : "";
}

/// SCENE run to its end in DIR/whole, and a copy of that folder continued in DIR/continued from
/// its `checkpoint`: the same output, bitwise.
void require_continues_bitwise(const std::string& scene, const fs::path& dir,
                               const std::vector<std::string>& args,
                               const std::string& checkpoint) {
  REQUIRE(fsi_run(scene, dir / "whole", args) == 0);
  fs::copy(dir / "whole", dir / "continued");
  auto restart = args;
  restart.insert(restart.end(), {"--restart", (dir / "continued" / checkpoint).string()});
  REQUIRE(fsi_run(scene, dir / "continued", restart) == 0);
  require_same_output(dir / "whole", dir / "continued");
}

/// Waits until `file` has at least `count` lines (the run is under way).
void wait_for_lines(const fs::path& file, std::size_t count) {
  for (int k = 0; k < 3000 && !(fs::exists(file) && lines(file) >= count); ++k)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  REQUIRE(lines(file) >= count);
}

/// `fsi run` of the coupled scene with ARGS into DIR/NAME (stdout and stderr in DIR), sent
/// `signal` once its probes.csv has `rows` lines; its exit status.
int signalled_run(const fs::path& dir, const std::string& name,
                  const std::vector<std::string>& args, std::size_t rows, int signal) {
  std::vector<std::string> all = {"run", coupled, "--out", (dir / name).string()};
  all.insert(all.end(), args.begin(), args.end());
  const pid_t pid = spawn(all, dir);
  wait_for_lines(dir / name / "probes.csv", rows);
  kill(pid, signal);
  return wait_status(pid);
}

} // namespace

TEST_CASE("apps: a checkpoint file gives back every value bit for bit", "[apps][reliability]") {
  using limits = std::numeric_limits<double>;
  const std::vector<double> reals = {
      1.0 / 3.0,    -0.0, limits::infinity(), limits::quiet_NaN(), limits::denorm_min(),
      limits::max()};
  const std::vector<std::int64_t> ints = {std::numeric_limits<std::int64_t>::min(), -1, 0,
                                          std::numeric_limits<std::int64_t>::max()};
  fsi::StateArchive a;
  a.put("fluid/hits/x", reals); // NaN is accepted in the wall-hit cache only
  a.put("fluid/hits/empty", std::vector<double>{});
  a.put("coupling/acceleration/column_steps", ints);
  a.put_real("driver/time", 0.1);
  const fs::path file = fresh("archive") / "checkpoint.h5";
  fsi::app::write_checkpoint(file, a);
  CHECK(!fs::exists(file.string() + ".tmp"));
  const fsi::StateArchive b = fsi::app::read_checkpoint(file);
  const auto& x = b.reals("fluid/hits/x", reals.size());
  CHECK(std::memcmp(x.data(), reals.data(), reals.size() * sizeof(double)) == 0);
  CHECK(b.reals("fluid/hits/empty").empty());
  CHECK(b.integers("coupling/acceleration/column_steps") == ints);
  CHECK(b.real("driver/time") == 0.1);
  CHECK(b.all_reals().size() == 3);
  CHECK_THROWS_WITH(b.reals("fluid/y"), "checkpoint: no entry 'fluid/y'");
  CHECK_THROWS_WITH(b.reals("fluid/hits/x", 7),
                    "checkpoint: 'fluid/hits/x' has 6 entries, this scene needs 7");
}

TEST_CASE("apps: a coupled run continued from a checkpoint is bitwise the uninterrupted run",
          "[apps][reliability]") {
  for (const std::string acceleration : {"iqn-ils", "aitken"}) {
    INFO(acceleration);
    const fs::path dir = fresh("restart_" + acceleration);
    const std::vector<std::string> args = {
        "--threads", "1",
        "--set",     "time.end=0.006",
        "--set",     "coupling.acceleration=" + acceleration,
        "--set",     "checkpoint={interval_steps: 100, keep: 5}"};
    require_continues_bitwise(coupled, dir, args, "checkpoint_000000100.h5");
    CHECK(columns(dir / "whole" / "coupling.csv", 8) ==
          columns(dir / "continued" / "coupling.csv", 8));
    CHECK(lines(dir / "continued" / "coupling.csv") == 301);
  }
}

TEST_CASE("apps: a fluid run with an adaptive step and a moving wall continues bitwise",
          "[apps][reliability]") {
  const fs::path dir = fresh("restart_fluid");
  const std::vector<std::string> args = {"--threads", "1", "--set",
                                         "checkpoint={interval_steps: 150, keep: 5}"};
  require_continues_bitwise(fluid, dir, args, "checkpoint_000000150.h5");
}

TEST_CASE("apps: a structure run continues bitwise", "[apps][reliability]") {
  const fs::path dir = fresh("restart_structure");
  const std::vector<std::string> args = {"--threads", "1",
                                         "--set",     "time.end=0.05",
                                         "--set",     "checkpoint={interval_steps: 20, keep: 5}"};
  require_continues_bitwise(structure, dir, args, "checkpoint_000000020.h5");
}

TEST_CASE("apps: a restart refuses a checkpoint that does not fit, before computing",
          "[apps][reliability]") {
  const fs::path dir = fresh("restart_mismatch");
  const std::vector<std::string> args = {"--threads",      "1",     "--set",
                                         "time.end=0.002", "--set", "checkpoint.interval_steps=50"};
  REQUIRE(fsi_run(coupled, dir / "run", args) == 0);
  const std::string checkpoint = (dir / "run" / "checkpoint_000000050.h5").string();
  std::string err;
  auto other_dt = args;
  other_dt.insert(other_dt.end(), {"--set", "time.dt=1e-5", "--restart", checkpoint});
  CHECK(fsi_run(coupled, dir / "run", other_dt, &err) == 2);
  CHECK(err.find(checkpoint + ": written with time.dt = ") != std::string::npos);
  auto other_mesh = args;
  other_mesh.insert(other_mesh.end(),
                    {"--set", "structures[0].mesh.elements_y=5", "--restart", checkpoint});
  CHECK(fsi_run(coupled, dir / "run", other_mesh, &err) == 2);
  CHECK(err.find("checkpoint: 'coupling/state/x' has ") != std::string::npos);
  auto missing = args;
  missing.insert(missing.end(), {"--restart", (dir / "none.h5").string()});
  CHECK(fsi_run(coupled, dir / "run", missing, &err) == 2);
  CHECK(err == (dir / "none.h5").string() + ": cannot open as an HDF5 checkpoint\n");
}

TEST_CASE("apps: SIGINT stops a run with a checkpoint that continues it bitwise",
          "[apps][reliability]") {
  const fs::path dir = fresh("sigint");
  const std::vector<std::string> args = {"--threads", "1", "--set", "output.interval=0.0002"};
  // Once probes.csv has its header, t = 0 and two frames.
  REQUIRE(signalled_run(dir, "stopped", args, 4, SIGINT) == 130);
  const std::string err = slurp(dir / "stderr.txt");
  CHECK(err.find("interrupted by signal 2 at step ") != std::string::npos);
  const fs::path checkpoint = json_text(dir / "stopped" / "run.json", "checkpoint");
  REQUIRE(fs::exists(checkpoint));
  CHECK(json_text(dir / "stopped" / "run.json", "status") == "interrupted");
  CHECK(!fs::exists(checkpoint.string() + ".tmp"));

  auto restart = args;
  restart.insert(restart.end(), {"--restart", checkpoint.string()});
  REQUIRE(fsi_run(coupled, dir / "stopped", restart) == 0);
  REQUIRE(fsi_run(coupled, dir / "whole", args) == 0);
  require_same_output(dir / "whole", dir / "stopped");
}

TEST_CASE("apps: SIGTERM stops a run with a checkpoint and exit status 143",
          "[apps][reliability]") {
  const fs::path dir = fresh("sigterm");
  REQUIRE(signalled_run(dir, "stopped", {"--threads", "1", "--set", "output.interval=0.0002"}, 3,
                        SIGTERM) == 143);
  CHECK(slurp(dir / "stderr.txt").find("interrupted by signal 15 at step ") != std::string::npos);
  CHECK(fs::exists(json_text(dir / "stopped" / "run.json", "checkpoint")));
}

TEST_CASE("apps: checkpoints by wall time keep the newest ones, whole", "[apps][reliability]") {
  const fs::path out = fresh("minutes") / "run";
  // A checkpoint after every step (1e-9 minutes), three kept.
  REQUIRE(fsi_run(fluid, out,
                  {"--threads", "1", "--set", "time.end=0.002", "--set",
                   "checkpoint={interval_minutes: 1.0e-9, keep: 3}"}) == 0);
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(out))
    if (e.path().filename().string().rfind("checkpoint_", 0) == 0)
      names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  const std::string steps = slurp(out / "run.json");
  const auto at = steps.find("\"steps\": ");
  REQUIRE(at != std::string::npos);
  const long last = std::stol(steps.substr(at + 9));
  char newest[48];
  std::snprintf(newest, sizeof newest, "checkpoint_%09ld.h5", last);
  REQUIRE(names.size() == 3);
  CHECK(names.back() == newest);
  // Each is a whole HDF5 file with the driver's clock.
  for (const auto& n : names)
    CHECK(fsi::app::read_dataset(out / n, "driver/step").values.size() == 1);
}

TEST_CASE("apps: after SIGKILL every frame fields.xmf names is readable in fields.h5",
          "[apps][reliability]") {
  const fs::path dir = fresh("sigkill");
  REQUIRE(signalled_run(dir, "killed", {"--threads", "1", "--set", "output.interval=0.0001"}, 6,
                        SIGKILL) == 128 + SIGKILL);

  // Every HDF dataset the XDMF index names opens with the dimensions it states.
  const int items = check_indexed_datasets(dir / "killed");
  const std::size_t frames = frames_in(dir / "killed" / "fields.xmf");
  CHECK(frames >= 5);
  CHECK(items >= static_cast<int>(frames) * 2);
}

namespace {
/// A guard: exit status 3, one line naming what, where and when, the last state on disk.
void require_guard(const std::string& scene, const std::string& name,
                   const std::vector<std::string>& args, const std::vector<std::string>& says) {
  const fs::path out = fresh("guard_" + name);
  std::string err;
  CHECK(fsi_run(scene, out, args, &err) == 3);
  INFO(err);
  CHECK(std::count(err.begin(), err.end(), '\n') == 1);
  CHECK(err.rfind("run stopped: ", 0) == 0);
  for (const auto& s : says) CHECK(err.find(s) != std::string::npos);
  CHECK(err.find("(last state: frame ") != std::string::npos);
  CHECK(fs::exists(out / "failed_state.h5"));
  CHECK(json_text(out / "run.json", "status") == "failed");
  // The last frame is the failed state, indexed in fields.xmf, with its row in probes.csv.
  CHECK(frames_in(out / "fields.xmf") == lines(out / "probes.csv") - 1);
  CHECK(frames_in(out / "fields.xmf") >= 2);
}
} // namespace

TEST_CASE("apps: guards stop the run with one message, the last state and exit status 3",
          "[apps][reliability]") {
  SECTION("non-finite fluid field") {
    require_guard(
        fluid, "nan",
        {"--threads", "1", "--set", "time={end: 2.0, dt: 2.0}", "--set", "gravity=[0, -1.0e308]"},
        {"fluid: non-finite position, velocity or pressure at particle ", "step 1", "t = 2 s"});
  }
  SECTION("a particle behind a wall") {
    require_guard(fluid, "wall", {"--threads", "1", "--set", "time={end: 0.1, dt: 0.005}"},
                  {"fluid: particle ", " is behind wall segment ", "step ", "t = "});
  }
  SECTION("Newton-Raphson does not converge") {
    require_guard(structure, "newton",
                  {"--threads", "1", "--set", "structures[0].newton.max_iterations=1"},
                  {"structure 'beam': Newton did not converge in 1 iterations",
                   "largest residual at node ", "structure step 1, t = 0.001"});
  }
  SECTION("an inverted element") {
    require_guard(
        structure, "inverted",
        {"--threads", "1", "--set", "structures[0].loads=[{boundary: right, force: [0, -1.0e9]}]"},
        {"structure 'beam': element ", "det F = ", "inverted element",
         "structure step 1, t = 0.001"});
  }
  SECTION("coupling does not converge within the scene's limit") {
    require_guard(coupled, "coupling",
                  {"--threads", "1", "--set", "coupling.max_iterations=2", "--set",
                   "coupling.stop_on_unconverged=true", "--set", "coupling.tolerance=1e-12"},
                  {"coupling (bgs): step 0 at t = 0 s did not converge in 2 iterations",
                   "largest at interface node "});
  }
}

/// The steps a run took on one thread (run.json's thread_governor.steps_at[0]).
long steps_on_one_thread(const fs::path& run_json) {
  const std::regex pattern("\"steps_at\": \\[([0-9]+)");
  std::smatch m;
  const std::string text = slurp(run_json);
  return std::regex_search(text, m, pattern) ? std::stol(m[1].str()) : -1;
}

TEST_CASE("apps: the same scene gives bitwise the same output, for one and for two threads",
          "[apps][reliability]") {
  const fs::path dir = fresh("determinism");
  // The thread governor's trials (one thread for up to 9 steps after the first 9 on two, then
  // 30, 60, ... steps apart) fall inside both runs (100 and 218 steps): a 2-thread run mixes
  // counts and must still match.
  for (const auto& [scene, end] :
       {std::pair{coupled, std::string("time.end=0.002")}, {fluid, std::string("time.end=0.01")}}) {
    INFO(scene);
    const fs::path a2 = dir / (fs::path(scene).stem().string() + "_a2"),
                   b2 = dir / (fs::path(scene).stem().string() + "_b2"),
                   c1 = dir / (fs::path(scene).stem().string() + "_c1"); // one run per folder
    REQUIRE(fsi_run(scene, a2, {"--threads", "2", "--set", end}) == 0);
    REQUIRE(fsi_run(scene, b2, {"--threads", "2", "--set", end}) == 0);
    REQUIRE(fsi_run(scene, c1, {"--threads", "1", "--set", end}) == 0);
    CHECK(steps_on_one_thread(a2 / "run.json") >= 1);
    CHECK(steps_on_one_thread(b2 / "run.json") >= 1);
    require_same_output(a2, b2);
    // Across thread counts the tolerance of docs/reliability.md is zero: bitwise equal.
    require_same_output(a2, c1);
  }
}
