// One-way verification modes: a CSS run records its interface (interface.h5); the structure
// under the recorded loads and the fluid against the recorded motion reproduce it bit for bit;
// recorded files are interpolated linearly in time; bad files are input errors (exit 2).
#include "fsi/core/error.hpp"
#include "fsi_app/cli.hpp"
#include "fsi_app/output/fields_file.hpp"
#include "fsi_app/output/interface_history.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <hdf5.h>
#include <sstream>

using namespace fsi;
using namespace fsi::app;
namespace fs = std::filesystem;

namespace {

const std::string kScene = FSI_TEST_DATA "/coupled_small.yaml";

// One thread: the runs compared are bitwise reproducible for a given thread count, and the
// shared test machine is not oversubscribed.
int fsi_cli(std::vector<std::string> args, std::string* err = nullptr) {
  if (args.front() == "run") args.insert(args.end(), {"--threads", "1"});
  std::ostringstream out, errors;
  const int status = run_cli(args, out, errors, false);
  if (err) *err = errors.str();
  return status;
}

/// Column `name` of probes.csv, as written (10 significant digits).
std::vector<std::string> probe_column(const fs::path& csv, const std::string& name) {
  std::ifstream in(csv);
  std::string line, cell;
  std::getline(in, line);
  std::stringstream header(line);
  int column = 0;
  while (std::getline(header, cell, ',') && cell != name) ++column;
  std::vector<std::string> values;
  while (std::getline(in, line)) {
    std::stringstream row(line);
    for (int k = 0; k <= column; ++k) std::getline(row, cell, ',');
    values.push_back(cell);
  }
  return values;
}

double max_abs(const std::vector<double>& v) {
  double m = 0.0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

} // namespace

TEST_CASE("apps: one-way replays of a recorded CSS run reproduce it exactly", "[apps][one_way]") {
  const fs::path root = fs::temp_directory_path() / "fsi_test_one_way";
  fs::remove_all(root);
  const fs::path coupled = root / "coupled", structure = root / "structure", fluid = root / "fluid";
  const std::string record = (coupled / "interface.h5").string();
  // coupled_small.yaml: css, predictor none, record_interface true, 1000 steps.
  REQUIRE(fsi_cli({"run", kScene, "--out", coupled.string()}) == 0);
  REQUIRE(fsi_cli({"run", kScene, "--out", structure.string(), "--set",
                   "coupling.scheme=one_way_structure", "--set", "coupling.loads=" + record}) == 0);
  REQUIRE(fsi_cli({"run", kScene, "--out", fluid.string(), "--set", "coupling.scheme=one_way_fluid",
                   "--set", "coupling.motion=" + record}) == 0);
  const auto read = [](const fs::path& dir, const std::string& set) {
    return read_dataset(dir / "interface.h5", set);
  };
  const auto time = read(coupled, "time");
  REQUIRE(time.dims == std::vector<std::size_t>{1001});
  CHECK(time.values.back() == 0.02);

  { // the structure under the recorded loads
    // The loads it took are the recorded ones, read back at the recorded times bit for bit.
    CHECK(read(structure, "load").values == read(coupled, "load").values);
    // CSS without predictor: the fluid's wall for step k -> k+1 is the structure at t_k, so the
    // coupled record's motion row k+1 is the structure's state after step k. The replayed
    // structure's own state (its record) must equal it exactly, at every interface node.
    for (const char* set : {"position", "velocity", "acceleration"}) {
      INFO(set);
      const auto c = read(coupled, set).values, s = read(structure, set).values;
      REQUIRE(c.size() == s.size());
      const std::size_t row = c.size() / 1001; // 53 nodes x 2
      CHECK(std::equal(s.begin(), s.end() - static_cast<long>(row),
                       c.begin() + static_cast<long>(row)));
    }
    const auto corner = probe_column(structure / "probes.csv", "corner_x");
    CHECK(corner == probe_column(coupled / "probes.csv", "corner_x"));
    CHECK(std::abs(std::stod(corner.back())) > 1e-4); // the obstacle did move (0.47 mm)
  }

  { // the fluid against the recorded motion
    for (const char* set : {"position", "velocity", "acceleration", "load"}) {
      INFO(set);
      CHECK(read(fluid, set).values == read(coupled, set).values);
    }
    CHECK(max_abs(read(coupled, "load").values) > 1.0); // the water does push (N/m)
    for (const char* probe : {"p_face", "fluid_ke"})
      CHECK(probe_column(fluid / "probes.csv", probe) ==
            probe_column(coupled / "probes.csv", probe));
    CHECK(std::stod(probe_column(fluid / "probes.csv", "p_face").back()) > 100.0);
  }
}

TEST_CASE("apps: a recorded interface is interpolated linearly in time", "[apps][one_way]") {
  const fs::path h5 = fs::temp_directory_path() / "fsi_test_interface_history.h5";
  // Two nodes, x = (t, -2t) + node, v = (3t, 1), a = (0, t), loads (5t, 7): linear in t.
  auto motion = [](double t) {
    coupling::InterfaceMotion m = coupling::InterfaceMotion::zeros(2);
    for (std::size_t i = 0; i < 2; ++i) {
      m.x[i] = Vec2(t + static_cast<double>(i), -2.0 * t);
      m.v[i] = Vec2(3.0 * t, 1.0);
      m.a[i] = Vec2(0.0, t);
    }
    return m;
  };
  auto loads = [](double t) {
    coupling::InterfaceLoads f = coupling::InterfaceLoads::zeros(2);
    for (auto& v : f.f) v = Vec2(5.0 * t, 7.0);
    return f;
  };
  const std::vector<double> times = {0.0, 0.1, 0.3, 0.7};
  {
    InterfaceHistoryWriter writer(h5, 2);
    for (double t : times) writer.append(t, motion(t), loads(t));
  }
  InterfaceHistory history(h5);
  CHECK(history.nodes() == 2);
  CHECK(history.first_time() == 0.0);
  CHECK(history.last_time() == 0.7);
  for (double t : times) { // recorded rows come back bit for bit
    CHECK(history.motion_at(t).x == motion(t).x);
    CHECK(history.loads_at(t).f == loads(t).f);
  }
  for (double t : {0.05, 0.2, 0.25, 0.5, 0.69}) {
    const auto m = history.motion_at(t), e = motion(t);
    const auto f = history.loads_at(t);
    for (std::size_t i = 0; i < 2; ++i) {
      CHECK((m.x[i] - e.x[i]).norm() < 1e-15);
      CHECK((m.v[i] - e.v[i]).norm() < 1e-15);
      CHECK((m.a[i] - e.a[i]).norm() < 1e-15);
      CHECK((f.f[i] - loads(t).f[i]).norm() < 1e-14);
    }
  }
  CHECK_THROWS_AS(history.motion_at(0.71), RunError);
  CHECK_THROWS_AS(history.loads_at(-0.01), RunError);
}

TEST_CASE("apps: bad recorded interface files are input errors before any step",
          "[apps][one_way]") {
  const fs::path root = fs::temp_directory_path() / "fsi_test_one_way_bad";
  fs::remove_all(root);
  const fs::path shorter = root / "short";
  REQUIRE(fsi_cli({"run", kScene, "--out", shorter.string(), "--set", "time.end=0.002", "--set",
                   "output.interval=0.002"}) == 0);
  const std::string record = (shorter / "interface.h5").string();
  // A file whose datasets disagree: /velocity has 4 nodes, /position 5.
  const fs::path mixed = root / "mixed.h5";
  {
    const hid_t file = H5Fcreate(mixed.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    const double zeros[3 * 5 * 2] = {};
    const double t[3] = {0.0, 0.01, 0.03};
    auto put = [&](const char* name, std::vector<hsize_t> dims, const double* data) {
      const hid_t space = H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr);
      const hid_t set =
          H5Dcreate2(file, name, H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
      H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data);
      H5Dclose(set);
      H5Sclose(space);
    };
    put("time", {3}, t);
    put("position", {3, 5, 2}, zeros);
    put("velocity", {3, 4, 2}, zeros);
    H5Fclose(file);
  }
  const auto fluid = [&](const std::string& file, std::vector<std::string> more = {}) {
    std::vector<std::string> args = {"run",   kScene,
                                     "--out", (root / "never").string(),
                                     "--set", "coupling.scheme=one_way_fluid",
                                     "--set", "coupling.motion=" + file};
    for (auto& m : more) args.push_back("--set"), args.push_back(m);
    std::string err;
    const int status = fsi_cli(args, &err);
    CHECK(status == 2);
    CHECK(std::count(err.begin(), err.end(), '\n') == 1);
    return err;
  };
  const std::string located = kScene + ": --set coupling.motion=";
  std::string err = fluid("/nonexistent/interface.h5");
  CHECK(err == located + "/nonexistent/interface.h5: coupling.motion: file not found: "
                         "/nonexistent/interface.h5\n");
  err = fluid(kScene);
  CHECK(err == located + kScene + ": coupling.motion: " + kScene + ": cannot open as HDF5\n");
  err = fluid((shorter / "fields.h5").string());
  CHECK(err.find("coupling.motion: " + (shorter / "fields.h5").string() + ": no dataset /time") !=
        std::string::npos);
  err = fluid(mixed.string());
  CHECK(err.find("coupling.motion: " + mixed.string() +
                 ": /velocity has dimensions [3 x 4 x 2], expected [3 x nodes x 2]") !=
        std::string::npos);
  err = fluid(record);
  CHECK(err.find("coupling.motion: " + record + ": records t = 0 .. 0.002 s, the run needs 0 .. " +
                 "0.02 s") != std::string::npos);
  // Another mesh: 6 elements high instead of 12, so 29 interface nodes where 53 were recorded.
  err = fluid(record, {"time.end=0.002", "structures[0].mesh.elements_y=6"});
  CHECK(err.rfind(kScene + ":", 0) == 0);
  CHECK(err.find(": coupling.motion: " + record +
                 " records 53 interface nodes, this interface "
                 "has 29") != std::string::npos);
  CHECK_FALSE(fs::exists(root / "never")); // nothing ran
  // The file key belongs to its scheme, and the scheme needs it.
  CHECK(fsi_cli({"check", kScene, "--set", "coupling.loads=" + record}, &err) == 2);
  CHECK(err.find("coupling.loads: scheme 'css' replays no recorded interface loads") !=
        std::string::npos);
  CHECK(fsi_cli({"check", kScene, "--set", "coupling.scheme=one_way_structure"}, &err) == 2);
  CHECK(err.find("coupling.loads: required key missing") != std::string::npos);
}
