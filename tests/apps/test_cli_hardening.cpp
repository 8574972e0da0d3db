// Issue 17, the command line and the run loop, through the real executable (FSI_EXECUTABLE, or
// the program named by the environment variable FSI_EXE, to replay these against an older build):
// each case is a failure the audit found, asserting the exit status and the one-line message.
#include "fsi_process.hpp"

#include <catch2/catch.hpp>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <sys/file.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace fs = std::filesystem;
using fsi_test::slurp;
using fsi_test::wait_status;

namespace {

const std::string data = FSI_TEST_DATA "/";
const std::string structure = data + "valid_structure.yaml";
const std::string fluid = data + "tiny_fluid.yaml";

std::string executable() {
  const char* e = std::getenv("FSI_EXE");
  return e && *e ? e : FSI_EXECUTABLE;
}

fs::path fresh(const std::string& name) {
  return fsi_test::fresh_dir("cli", name);
}

void write(const fs::path& file, const std::string& text) {
  std::ofstream(file) << text;
}

pid_t spawn(const std::vector<std::string>& args, const fs::path& logs) {
  return fsi_test::spawn(executable(), args, logs);
}

struct Result {
  int status = 0;
  std::string out, err;
};

Result fsi(const std::vector<std::string>& args, double timeout_s = 120.0) {
  static int calls = 0;
  const fs::path logs = fresh("logs_" + std::to_string(getpid()) + "_" + std::to_string(calls++));
  Result r;
  r.status = wait_status(spawn(args, logs), timeout_s);
  r.out = slurp(logs / "stdout.txt");
  r.err = slurp(logs / "stderr.txt");
  fs::remove_all(logs);
  return r;
}

std::size_t lines(const std::string& s) {
  return static_cast<std::size_t>(std::count(s.begin(), s.end(), '\n'));
}

/// A clear error: exit 2, one line, containing every piece of `parts`.
void require_clear(const Result& r, const std::vector<std::string>& parts) {
  INFO(r.err);
  CHECK(r.status == 2);
  CHECK(lines(r.err) == 1);
  CHECK(r.err.find("internal error") == std::string::npos);
  for (const auto& p : parts) CHECK(r.err.find(p) != std::string::npos);
}

/// Whether a signal waits for delivery to `pid` (/proc/PID/status ShdPnd or SigPnd non-zero).
bool signal_pending(pid_t pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/status");
  for (std::string line; std::getline(in, line);)
    if ((line.rfind("ShdPnd:", 0) == 0 || line.rfind("SigPnd:", 0) == 0) &&
        line.find_first_not_of("0\t ", 7) != std::string::npos)
      return true;
  return false;
}

std::string json_field(const std::string& json, const std::string& key) {
  const std::regex re("\"" + key + "\": (\"[^\"]*\"|[^,\\n}]*)");
  std::smatch m;
  if (!std::regex_search(json, m, re)) return {};
  std::string v = m[1];
  if (!v.empty() && v.front() == '"') v = v.substr(1, v.size() - 2);
  return v;
}

std::set<std::string> listing(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir))
    names.insert(e.path().filename().string() + ":" +
                 std::to_string(fs::last_write_time(e.path()).time_since_epoch().count()) + ":" +
                 std::to_string(e.is_regular_file() ? fs::file_size(e.path()) : 0));
  return names;
}

/// tiny_fluid.yaml with `replace` applied (each pair: text, replacement), as a new scene file.
fs::path variant(const fs::path& dir, const std::string& name,
                 const std::vector<std::pair<std::string, std::string>>& replace) {
  std::string text = slurp(fluid);
  for (const auto& [from, to] : replace) {
    const auto at = text.find(from);
    REQUIRE(at != std::string::npos);
    text.replace(at, from.size(), to);
  }
  const fs::path file = dir / name;
  write(file, text);
  return file;
}

} // namespace

TEST_CASE("apps: cli: --threads above the processors is refused with the number", "[apps][cli]") {
  const fs::path out = fresh("threads");
  const unsigned processors = std::thread::hardware_concurrency();
  const auto r = fsi({"run", structure, "--out", (out / "o").string(), "--threads", "100000"});
  require_clear(r, {"--threads 100000", "this machine has"});
  if (processors > 0)
    CHECK(r.err.find("has " + std::to_string(processors) + " processor") != std::string::npos);
  CHECK(!fs::exists(out / "o"));
}

TEST_CASE("apps: cli: more than 1e9 fixed steps are refused up front with the count",
          "[apps][cli]") {
  const fs::path out = fresh("steps");
  auto r = fsi({"run", structure, "--out", (out / "a").string(), "--set", "time.dt=1e-300"});
  require_clear(r, {"valid_structure.yaml", "time.dt", "1e+298 steps", "at most 1e9"});
  CHECK(!fs::exists(out / "a" / "run.json"));
  r = fsi({"check", structure, "--set", "time.end=1e300"});
  require_clear(r, {"valid_structure.yaml", "1e+303 steps"});
}

TEST_CASE("apps: cli: an adaptive step below the floor stops with exit 3; the end is exact",
          "[apps][cli]") {
  const fs::path out = fresh("floor");
  auto r = fsi({"run", fluid, "--out", (out / "a").string(), "--set", "time.courant=1e-300"});
  INFO(r.err);
  CHECK(r.status == 3);
  CHECK(r.err.find("run stopped: time step: the stable step is") != std::string::npos);
  CHECK(r.err.find("above the limit of 1e+09") != std::string::npos);
  CHECK(r.err.find("ETA -") == std::string::npos);
  CHECK(json_field(slurp(out / "a" / "run.json"), "status") == "failed");
  // A fixed step that does not divide time.end: the last step is shortened to end there.
  r = fsi({"run", structure, "--out", (out / "b").string(), "--set", "time.dt=0.003"});
  CHECK(r.status == 0);
  CHECK(std::stod(json_field(slurp(out / "b" / "run.json"), "simulated_time")) == 0.01);
  const std::string probes = slurp(out / "b" / "probes.csv");
  CHECK(probes.substr(probes.rfind('\n', probes.size() - 2) + 1).rfind("0.01,", 0) == 0);
  CHECK(r.err.find("100.0 %") != std::string::npos);
  CHECK(r.err.find("ETA -") == std::string::npos);
}

TEST_CASE("apps: cli: duplicate YAML keys and a second document are errors naming the lines",
          "[apps][cli]") {
  const fs::path dir = fresh("duplicates");
  std::string text = slurp(structure);
  const auto at = text.find("      density: 1200.0\n");
  REQUIRE(at != std::string::npos);
  write(dir / "density.yaml",
        text.substr(0, at) + "      density: 1200.0\n      density: -5\n" + text.substr(at + 22));
  auto r = fsi({"check", (dir / "density.yaml").string()});
  require_clear(r, {"density.yaml:25: structures[0].material.density: duplicate key (first on "
                    "line 24)"});
  write(dir / "time.yaml", slurp(structure) + "time:\n  end: 1.0\n  dt: 0.5\n");
  r = fsi({"check", (dir / "time.yaml").string()});
  require_clear(r, {"time.yaml:29: time: duplicate key (first on line 3)"});
  // An empty key twice (a fuzz finding: the message named no key) is named "".
  write(dir / "empty.yaml", slurp(structure) + "\"\": 1\n\"\": 2\n");
  r = fsi({"check", (dir / "empty.yaml").string()});
  require_clear(r, {"empty.yaml:30: \"\": duplicate key (first on line 29)"});
  write(dir / "two.yaml", slurp(structure) + "---\nname: other\n");
  r = fsi({"check", (dir / "two.yaml").string()});
  require_clear(r, {"two.yaml:29: yaml: a second YAML document"});
}

TEST_CASE("apps: cli: a motion table that does not cover the run is refused naming the key",
          "[apps][cli]") {
  const fs::path dir = fresh("tables");
  write(dir / "short.csv", "time,angle\n0,0\n0.001,0.01\n");
  write(dir / "late.csv", "time,angle\n1,0\n2,0.01\n");
  write(dir / "empty.csv", "");
  write(dir / "binary.csv", std::string("\x01\x02\x03garbage\n\xff\xfe,1\n", 17));
  const std::string sinusoid =
      "      kind: sinusoid\n      dof: rotation\n      pivot: [0.0, 0.0]\n"
      "      amplitude: 0.05\n      period: 0.1\n";
  for (const auto& [table, expected] : std::vector<std::pair<std::string, std::string>>{
           {"short.csv", "short.csv: covers t = 0 .. 0.001 s, the run needs 0 .. 0.02 s"},
           {"late.csv", "late.csv: covers t = 1 .. 2 s, the run needs 0 .. 0.02 s"},
           {"empty.csv", "empty.csv: 0 rows of numbers; a table needs at least two"},
           {"binary.csv", "binary.csv:2: not a row of numbers: '\\xff\\xfe,1'"}}) {
    const fs::path scene =
        variant(dir, table + ".yaml",
                {{sinusoid, "      kind: table\n      table: " + table + "\n      unit: rad\n"}});
    const auto r = fsi({"check", scene.string()});
    require_clear(r, {table + ".yaml:", "walls[2].motion.table: ", expected});
    CHECK(r.err.find(":0:") == std::string::npos);
  }
  // The explicit option to hold the end values.
  const fs::path held =
      variant(dir, "held.yaml",
              {{sinusoid,
                "      kind: table\n      table: short.csv\n      unit: rad\n      hold: true\n"}});
  const auto r = fsi({"check", held.string()});
  INFO(r.err);
  CHECK(r.status == 0);
}

TEST_CASE("apps: cli: after SIGINT the continue command carries --set and --threads; the "
          "checkpoint holds the overrides",
          "[apps][cli]") {
  const fs::path dir = fresh("sigint");
  const fs::path out = dir / "run";
  const std::vector<std::string> args = {"run",   fluid,        "--out",     out.string(),
                                         "--set", "time.end=2", "--threads", "1"};
  const pid_t pid = spawn(args, dir);
  for (int i = 0; i < 3000 && !fs::exists(out / "probes.csv"); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  kill(pid, SIGINT);
  REQUIRE(wait_status(pid, 120.0) == 130);
  const std::string err = slurp(dir / "stderr.txt");
  INFO(err);
  const std::smatch m = [&] {
    std::smatch s;
    std::regex_search(err, s,
                      std::regex("continue with: fsi run (\\S+) --out (\\S+) --set "
                                 "time.end=2 --threads 1 --restart (\\S+)"));
    return s;
  }();
  REQUIRE(!m.empty());
  const std::string checkpoint = m[3];
  CHECK(json_field(slurp(out / "run.json"), "status") == "interrupted");
  // Without the overrides: refused, naming the difference.
  auto r = fsi({"run", fluid, "--out", out.string(), "--restart", checkpoint});
  require_clear(r, {checkpoint + ": written with --set time.end=2, this run has no --set",
                    "missing: --set time.end=2"});
  r = fsi({"run", fluid, "--out", out.string(), "--set", "fluid.viscosity=2e-6", "--set",
           "time.end=2", "--restart", checkpoint});
  require_clear(r, {"not in the checkpoint: --set fluid.viscosity=2e-6"});
  // The printed overrides plus a time.end of its own (allowed: extending or shortening a
  // run): continues to exactly that end.
  std::smatch t;
  REQUIRE(std::regex_search(err, t, std::regex(", t = (\\S+) s;")));
  char end[32];
  std::snprintf(end, sizeof end, "%.6g", std::stod(t[1]) + 0.004);
  r = fsi({"run", fluid, "--out", out.string(), "--set", "time.end=2", "--set",
           std::string("time.end=") + end, "--threads", "1", "--restart", checkpoint});
  INFO(r.err);
  CHECK(r.status == 0);
  CHECK(std::stod(json_field(slurp(out / "run.json"), "simulated_time")) == std::stod(end));
}

TEST_CASE("apps: cli: a double Ctrl-C leaves run.json saying interrupted", "[apps][cli]") {
  const fs::path dir = fresh("double");
  const fs::path out = dir / "run";
  // 16 times the particles: a step lasts several ms, so the second signal lands inside one.
  const pid_t pid = spawn(
      {"run", fluid, "--out", out.string(), "--set", "time.end=2", "--set", "fluid.l0=1e-3"}, dir);
  for (int i = 0; i < 3000 && !fs::exists(out / "probes.csv"); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  // Two separate signals: the second is sent once the first has left the pending set (two
  // sent back to back would merge into one).
  kill(pid, SIGINT);
  for (int i = 0; i < 1000 && signal_pending(pid); ++i)
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  kill(pid, SIGINT);
  CHECK(wait_status(pid, 120.0) == 130);
  const std::string json = slurp(out / "run.json");
  INFO(slurp(dir / "stderr.txt"));
  CHECK(json_field(json, "status") == "interrupted");
  CHECK(!fs::exists(out / "run.json.tmp"));
}

TEST_CASE("apps: cli: one run per output folder; a folder of another run needs --overwrite",
          "[apps][cli]") {
  const fs::path dir = fresh("lock");
  const fs::path out = dir / "run";
  fs::create_directories(out);
  // Another run holds the folder (its lock): refused, nothing touched.
  const int fd = open((out / ".lock").c_str(), O_RDWR | O_CREAT, 0644);
  REQUIRE(fd >= 0);
  REQUIRE(flock(fd, LOCK_EX | LOCK_NB) == 0);
  const auto before = listing(out);
  auto r = fsi({"run", structure, "--out", out.string()});
  require_clear(r, {out.string() + ": --out: another fsi run is writing to this folder"});
  CHECK(listing(out) == before);
  close(fd);
  // A finished run, then an unrelated file and a stale checkpoint of an older run.
  r = fsi({"run", structure, "--out", out.string()});
  REQUIRE(r.status == 0);
  write(out / "notes.txt", "mine");
  write(out / "checkpoint_000000999.h5", "old");
  write(out / "coupling.csv", "old");
  const auto finished = listing(out);
  r = fsi({"run", structure, "--out", out.string(), "--set", "time.end=0.005"});
  require_clear(r, {out.string() + ": --out holds the files of an earlier run", "--overwrite"});
  CHECK(listing(out) == finished);
  r = fsi({"run", structure, "--out", out.string(), "--set", "time.end=0.005", "--overwrite"});
  CHECK(r.status == 0);
  CHECK(fs::exists(out / "notes.txt"));
  CHECK(!fs::exists(out / "checkpoint_000000999.h5"));
  CHECK(!fs::exists(out / "coupling.csv"));
  CHECK(json_field(slurp(out / "run.json"), "simulated_time") == "0.005");
}

TEST_CASE("apps: cli: bad scene and output paths get one clear line, exit 2", "[apps][cli]") {
  const fs::path dir = fresh("paths");
  require_clear(fsi({"check", dir.string()}), {dir.string() + ": is a directory"});
  REQUIRE(mkfifo((dir / "fifo.yaml").c_str(), 0644) == 0);
  require_clear(fsi({"check", (dir / "fifo.yaml").string()}, 20.0), {"not a regular file"});
  require_clear(fsi({"check", "/dev/zero"}, 20.0), {"/dev/zero: not a regular file"});
  write(dir / "big.yaml", std::string((16u << 20) + 1, '#'));
  require_clear(fsi({"check", (dir / "big.yaml").string()}), {"bytes; a scene file is at most 16"});
  write(dir / "file", "x");
  require_clear(fsi({"run", structure, "--out", (dir / "file").string()}),
                {"file: --out: exists and is not a folder"});
  require_clear(fsi({"run", structure, "--out", (dir / "file" / "sub").string()}),
                {"--out: cannot create the folder"});
  require_clear(fsi({"run", structure, "--out", "/proc/fsi_test_out"}), {"/proc/fsi_test_out"});
  // --set errors name the scene file; a block an override created says so.
  require_clear(fsi({"check", structure, "--set", "time..end=1"}),
                {structure + ": --set time..end=1: "});
  require_clear(fsi({"check", structure, "--set", "fluid.l0=0.01"}),
                {structure + ": --set fluid.l0=0.01: fluid.density: required key missing",
                 "--set fluid.l0=0.01 created it"});
  // fsi run --help; check takes no run options.
  auto r = fsi({"run", "--help"});
  CHECK(r.status == 0);
  CHECK(r.out.find("fsi run SCENE --out DIR") != std::string::npos);
  require_clear(fsi({"check", structure, "--out", "x"}), {"fsi check: --out is for fsi run"});
  require_clear(fsi({"check", structure, "--restart", "x.h5"}),
                {"fsi check: --restart is for fsi run"});
}

TEST_CASE("apps: cli: fsi check builds no solver: a 300 x 300 rectangle and 3 million particles "
          "check in a few hundred MB",
          "[apps][cli]") {
  // Before, check built the whole model: 2.35 GB for the rectangle, 1.6 GB for 3 million
  // particles. Now each plug-in's validate reads and checks the input only.
  const std::vector<std::vector<std::string>> cases = {
      {"check", structure, "--set", "structures[0].mesh.elements_x=300", "--set",
       "structures[0].mesh.elements_y=300"},
      {"check", FSI_SOURCE_DIR "/data/scenes/dam_break_elastic_obstacle.yaml", "--set",
       "fluid.l0=1.5e-4"}};
  for (const auto& args : cases) {
    INFO(args[1]);
    const fs::path logs = fresh("check_memory");
    const pid_t pid = spawn(args, logs);
    int status = 0;
    rusage usage{};
    REQUIRE(wait4(pid, &status, 0, &usage) == pid);
    CHECK(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 0);
    CHECK(slurp(logs / "stdout.txt").ends_with(": ok\n"));
    CHECK(usage.ru_maxrss < 512 * 1024); // kB
  }
}
