// interface.h5 in 3-D: the 3-D hydrostatic plate (SPH + T10, data/scenes/hydrostatic_plate_3d.yaml)
// shortened to three coupling steps records its interface; the per-point loads sum to the totals
// of coupling.csv, the motion rows are the structure's interface nodes, the faces its 6-node
// faces; the one-way replays of the record reproduce the coupled run bit for bit.
#include "fsi_app/cli.hpp"
#include "fsi_app/coupled_model.hpp"
#include "fsi_app/output/fields_file.hpp"
#include "fsi_app/scene.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace fsi;
using namespace fsi::app;
namespace fs = std::filesystem;

namespace {

const std::string kPlate = FSI_SOURCE_DIR "/data/scenes/hydrostatic_plate_3d.yaml";
constexpr int kSteps = 3; // time.end = 0.003 s at the scene's dt = 1e-3 s

/// coupling.csv's rows after the header: the last three columns (fx_total, fy_total, fz_total).
std::vector<Vec3> csv_totals(const fs::path& csv) {
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  REQUIRE(line.ends_with(",fx_total,fy_total,fz_total"));
  std::vector<Vec3> totals;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::stringstream row(line);
    for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
    const std::size_t n = cells.size();
    totals.emplace_back(std::stod(cells[n - 3]), std::stod(cells[n - 2]), std::stod(cells[n - 1]));
  }
  return totals;
}

/// Row `k` of a [rows x n x 3] dataset as n points.
std::vector<Vec3> row_of(const Dataset& set, std::size_t k) {
  const std::size_t n = set.dims[1];
  std::vector<Vec3> out(n);
  for (std::size_t i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c)
      out[i][c] = set.values[(k * n + i) * 3 + static_cast<std::size_t>(c)];
  return out;
}

/// `fsi ARGS` on one thread, three steps, recording interface.h5.
int fsi_cli(std::vector<std::string> args) {
  args.insert(args.end(), {"--threads", "1", "--set", "time.end=0.003", "--set",
                           "output.interval=0.001", "--set", "coupling.record_interface=true"});
  std::ostringstream out, errors;
  const int status = run_cli(args, out, errors, false);
  if (status != 0) UNSCOPED_INFO(errors.str());
  return status;
}

} // namespace

TEST_CASE("apps: 3-D interface.h5: loads sum to coupling.csv's totals, motion is the structure's",
          "[apps][sph][3d][coupled][interface_h5]") {
  const fs::path out = fs::temp_directory_path() / "fsi_test_interface_h5_3d";
  fs::remove_all(out);
  fs::create_directories(out);
  const Scene scene = load_scene(kPlate, {"coupling.record_interface=true"});
  const double dt = *scene.time.dt;
  std::vector<coupling::InterfaceMotion3> structure; // the structure's nodes before each step
  InterfaceMesh3 mesh;
  {
    CoupledModel3 model(scene);
    mesh = model.structure(0).interface_mesh3();
    model.open_logs(out, false);
    const coupling::StructureSolver3& S = model.structure(0).coupling_solver3();
    for (int k = 0; k < kSteps; ++k) {
      structure.push_back(S.interface_motion());
      model.advance(k * dt, dt);
    }
    model.flush_logs();
  } // interface.h5 closed
  const std::size_t n = mesh.node_count();
  const Dataset time = read_dataset(out / "interface.h5", "time");
  REQUIRE(time.dims == std::vector<std::size_t>{kSteps + 1});
  CHECK_THAT(time.values[kSteps], Catch::Matchers::WithinRel(kSteps * dt, 1e-15));

  // The faces: the plate's 6-node top faces, as its interface numbers them.
  const Dataset faces = read_dataset(out / "interface.h5", "faces");
  REQUIRE(faces.dims == std::vector<std::size_t>{mesh.faces.size(), 6});
  for (std::size_t f = 0; f < mesh.faces.size(); ++f)
    for (std::size_t j = 0; j < 6; ++j)
      CHECK(faces.values[f * 6 + j] == static_cast<double>(mesh.faces[f][j]));

  // CSS without predictor: row j >= 1 is the structure before step j - 1, row 0 the start.
  const Dataset x = read_dataset(out / "interface.h5", "position");
  const Dataset v = read_dataset(out / "interface.h5", "velocity");
  const Dataset a = read_dataset(out / "interface.h5", "acceleration");
  REQUIRE(x.dims == std::vector<std::size_t>{kSteps + 1, n, 3});
  CHECK(row_of(x, 0) == mesh.X0);
  for (std::size_t j = 1; j <= kSteps; ++j) {
    INFO("row " << j);
    CHECK(row_of(x, j) == structure[j - 1].x);
    CHECK(row_of(v, j) == structure[j - 1].v);
    CHECK(row_of(a, j) == structure[j - 1].a);
  }

  // The loads: row j >= 1 sums to coupling.csv's step j - 1 (17 digits) to round-off.
  const Dataset load = read_dataset(out / "interface.h5", "load");
  const std::vector<Vec3> totals = csv_totals(out / "coupling.csv");
  REQUIRE(totals.size() == kSteps);
  for (std::size_t j = 1; j <= kSteps; ++j) {
    Vec3 sum = Vec3::Zero();
    for (const Vec3& f : row_of(load, j)) sum += f;
    INFO("row " << j << ": sum " << sum.transpose() << " N, coupling.csv "
                << totals[j - 1].transpose() << " N");
    CHECK((sum - totals[j - 1]).norm() <= 1e-14 * totals[j - 1].norm());
    CHECK(sum.y() < -100.0); // the water pushes the plate down (rho g H A = 4905 N)
  }
}

TEST_CASE("apps: 3-D one-way replays of a recorded CSS run reproduce it exactly",
          "[apps][sph][3d][coupled][interface_h5]") {
  const fs::path root = fs::temp_directory_path() / "fsi_test_one_way_3d";
  fs::remove_all(root);
  const fs::path coupled = root / "coupled", structure = root / "structure", fluid = root / "fluid";
  const std::string record = (coupled / "interface.h5").string();
  REQUIRE(fsi_cli({"run", kPlate, "--out", coupled.string()}) == 0);
  REQUIRE(fsi_cli({"run", kPlate, "--out", structure.string(), "--set",
                   "coupling.scheme=one_way_structure", "--set", "coupling.loads=" + record}) == 0);
  REQUIRE(fsi_cli({"run", kPlate, "--out", fluid.string(), "--set", "coupling.scheme=one_way_fluid",
                   "--set", "coupling.motion=" + record}) == 0);
  const auto read = [](const fs::path& dir, const std::string& set) {
    return read_dataset(dir / "interface.h5", set).values;
  };
  // The structure under the recorded loads: its own motion is the coupled record one row later.
  CHECK(read(structure, "load") == read(coupled, "load"));
  for (const char* set : {"position", "velocity", "acceleration"}) {
    INFO(set);
    const auto c = read(coupled, set), s = read(structure, set);
    REQUIRE(c.size() == s.size());
    const auto row = static_cast<long>(c.size() / (kSteps + 1));
    CHECK(std::equal(s.begin(), s.end() - row, c.begin() + row));
  }
  // The fluid against the recorded motion: the same loads, bit for bit.
  for (const char* set : {"position", "velocity", "acceleration", "load"}) {
    INFO(set);
    CHECK(read(fluid, set) == read(coupled, set));
  }
  const auto load = read(coupled, "load");
  CHECK(*std::min_element(load.begin(), load.end()) < -1.0); // the water does push (N)
}
