// `mpirun -np N fsi run` (issue 47): the small dam breaks of data/dam_break_ranks.yaml (2-D) and
// data/dam_break_ranks_3d.yaml (3-D, triangle walls) on 1, 2 and 4 ranks against one process,
// through the files a user gets (probes.csv, fields.h5, run.json), bad input under mpirun: exit 2,
// the message printed once, and a run that fails on some ranks only: exit 3 on every rank, the
// failing rank's message once, the files kept; checkpoints restarted on another rank count; coupled
// scenes (data/walhorn_ranks.yaml, an implicit scheme, a coupled checkpoint; a 3-D EMPS fluid on a
// T10 plate; SPH fluids on structures, 2-D and 3-D) against one process; SPH checkpoints;
// fields.h5 written collectively (the one-process file), and failing on one rank (agreed).
// A plain program (not under mpiexec) that starts mpirun itself.
#include <catch2/catch.hpp>
#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace {

namespace fs = std::filesystem;
const std::string dam_break = std::string(FSI_TEST_DATA) + "/dam_break_ranks.yaml";

/// This process's folder for logs and runs, so two test programs at once (two builds on one
/// machine) do not share files.
const fs::path& scratch() {
  static const fs::path dir = [] {
    const fs::path d = fs::temp_directory_path() / ("fsi_ranks_" + std::to_string(getpid()));
    fs::create_directories(d);
    return d;
  }();
  return dir;
}

struct Outcome {
  int status = -1;
  std::string output; // stdout and stderr
};

std::string text_of(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// Runs `fsi ARGS` under mpirun on `np` ranks (np = 0: without mpirun); with `limit` seconds,
/// killed after them (status 124, a hang).
Outcome fsi(int np, const std::string& args, int limit = 0) {
  const fs::path log = scratch() / "fsi_ranks_log.txt";
  std::string command = std::string(FSI_EXE) + " " + args;
  if (np > 0)
    command = std::string(FSI_MPIEXEC) + " --oversubscribe --allow-run-as-root -np " +
              std::to_string(np) + " " + command;
  if (limit > 0) command = "timeout -k 10 " + std::to_string(limit) + " " + command;
  const int raw = std::system((command + " > " + log.string() + " 2>&1").c_str());
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, text_of(log)};
}

/// Runs `scene` on `np` ranks (0: without mpirun) with `args` (overrides) into a fresh folder,
/// named after the scene and `tag`.
fs::path run(const std::string& scene, int np, const std::string& args = "",
             const std::string& tag = "") {
  const std::string name = fs::path(scene).stem().string() + tag;
  const fs::path out = scratch() / (name + "_np" + std::to_string(np));
  fs::remove_all(out);
  const Outcome o = fsi(np, "run " + scene + " --out " + out.string() + " --threads 1 " + args);
  INFO(o.output);
  REQUIRE(o.status == 0);
  return out;
}

/// probes.csv: the rows of numbers (time first), the header skipped.
std::vector<std::vector<double>> probes(const fs::path& out) {
  std::ifstream in(out / "probes.csv");
  std::string line;
  std::getline(in, line);
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::stringstream cells(line);
    std::string cell;
    while (std::getline(cells, cell, ',')) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}

/// One dataset of an HDF5 file, flattened.
std::vector<double> dataset(const fs::path& h5, const std::string& path) {
  const hid_t file = H5Fopen(h5.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  REQUIRE(file >= 0);
  const hid_t set = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
  REQUIRE(set >= 0);
  const hid_t space = H5Dget_space(set);
  std::vector<double> values(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
  H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
  H5Sclose(space);
  H5Dclose(set);
  H5Fclose(file);
  return values;
}

/// One dataset of fields.h5 (frames/<k>/<grid>/<name>), flattened.
std::vector<double> field(const fs::path& out, int frame, const std::string& name,
                          const std::string& grid = "particles") {
  return dataset(out / "fields.h5", "frames/" + std::to_string(frame) + "/" + grid + "/" + name);
}

int frames(const fs::path& out) {
  const hid_t file = H5Fopen((out / "fields.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  REQUIRE(file >= 0);
  H5G_info_t info;
  H5Gget_info_by_name(file, "frames", &info, H5P_DEFAULT);
  H5Fclose(file);
  return static_cast<int>(info.nlinks);
}

/// Largest |a - b| over two equal-length lists (infinity when the lengths differ).
double max_difference(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) return INFINITY;
  double d = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) d = std::max(d, std::abs(a[i] - b[i]));
  return d;
}

double max_abs(const std::vector<double>& a) {
  double m = 0.0;
  for (const double v : a) m = std::max(m, std::abs(v));
  return m;
}

std::size_t occurrences(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

/// What `scene` run by mpirun at each of `nps` (1 first) differs by from plain `fsi run`
/// (probes.csv) and from np = 1 (fields.h5, in global id order): the largest probe difference
/// relative to the probe's largest |value| and the largest |dx|, |dv|, |dp| over the frames,
/// checked against those bounds. `rows`: the frames expected.
struct Bounds {
  double x, v, p;
};
void check_against_one_process(const std::string& scene, std::size_t rows_expected,
                               const Bounds& bounds, std::initializer_list<int> nps = {1, 2, 4}) {
  const fs::path serial = run(scene, 0), one = run(scene, 1);
  const auto reference = probes(serial);
  REQUIRE(reference.size() == rows_expected);
  // np = 1 under mpirun steps the decomposed fluid on one rank: the same sums in the same order
  // as the serial fluid (tests/parallel/test_emps.cpp), so the probes are bitwise the serial
  // ones but for the gathered id order of the particles they sum over.
  for (const int np : nps) {
    const fs::path out = np == 1 ? one : run(scene, np);
    const auto rows = probes(out);
    REQUIRE(rows.size() == reference.size());
    double worst = 0.0; // relative to each probe's largest |value|
    for (std::size_t k = 1; k < reference[0].size(); ++k) {
      std::vector<double> a, b;
      for (std::size_t r = 0; r < rows.size(); ++r)
        a.push_back(rows[r][k]), b.push_back(reference[r][k]);
      worst = std::max(worst, max_difference(a, b) / max_abs(b));
    }
    // Fields in global id order: compare np = 2, 4 with np = 1 entry by entry.
    REQUIRE(frames(out) == frames(one));
    double dx = 0, dv = 0, dp = 0, p_max = 0;
    for (int f = 0; f < frames(one); ++f) {
      dx = std::max(dx, max_difference(field(out, f, "position"), field(one, f, "position")));
      dv = std::max(dv, max_difference(field(out, f, "velocity"), field(one, f, "velocity")));
      dp = std::max(dp, max_difference(field(out, f, "pressure"), field(one, f, "pressure")));
      p_max = std::max(p_max, max_abs(field(one, f, "pressure")));
    }
    std::printf("fsi run %s np=%d: probes max relative difference %.2e against one process; "
                "fields against np=1: |dx| %.2e m, |dv| %.2e m/s, |dp| %.2e Pa (p max %.0f Pa)\n",
                fs::path(scene).stem().c_str(), np, worst, dx, dv, dp, p_max);
    const std::string json = text_of(out / "run.json");
    CHECK(occurrences(json, "\"processes\": " + std::to_string(np)) == 1);
    CHECK(occurrences(json, "\"status\": \"completed\"") == 1);
    CHECK(p_max > 100.0);
    // probes.csv holds 10 significant digits: a round-off difference of a probe may flip its
    // last digit, 1e-9 of the value at most.
    CHECK(worst <= 1e-9);
    CHECK(dx <= bounds.x);
    CHECK(dv <= bounds.v);
    CHECK(dp <= bounds.p);
  }
}

/// Frame `f`'s particles as rows (every dataset's values of a particle, `names` in order),
/// sorted: one process holds its particles in cell order, mpirun in id order.
std::vector<std::vector<double>> sorted_rows(const fs::path& out, int f,
                                             const std::vector<std::string>& names) {
  std::vector<std::vector<double>> rows(field(out, f, "pressure").size()); // one a particle
  for (const auto& name : names) {
    const std::vector<double> values = field(out, f, name);
    const std::size_t k = rows.empty() ? 0 : values.size() / rows.size();
    for (std::size_t i = 0; i < rows.size(); ++i)
      rows[i].insert(rows[i].end(), values.begin() + static_cast<std::ptrdiff_t>(k * i),
                     values.begin() + static_cast<std::ptrdiff_t>(k * (i + 1)));
  }
  std::sort(rows.begin(), rows.end());
  return rows;
}

} // namespace

TEST_CASE("mpirun -np N fsi run gives the one-process files", "[mpi]") {
  // t = 0 and every second step of 40. Round-off of pair sums in another order (test_emps.cpp).
  // Measured at np = 2, 4: |dx| <= 1.3e-16 m, |dv| <= 1.4e-13 m/s, |dp| <= 3.9e-9 Pa; no probe
  // digit differs at np = 1, 2, 4. p = c^2 rho (pnd - n0) / n0 with c^2 rho = 4e5 Pa: a
  // relative round-off e of pnd is 4e5 e Pa, 3.9e-9 Pa is e = 1e-14. Bounds about ten times
  // those.
  constexpr double c2_rho = 20.0 * 20.0 * 1000.0; // the scene's sound speed and density
  check_against_one_process(dam_break, 21, {1e-15, 1e-12, 1e-13 * c2_rho});
}

TEST_CASE("mpirun -np N fsi run of a 3-D scene gives the one-process files", "[mpi]") {
  // data/dam_break_ranks_3d.yaml: t = 0 and every 20th step of 200. Measured at np = 2, 4:
  // |dx| <= 1.1e-16 m, |dv| <= 2.4e-14 m/s, |dp| <= 9.1e-10 Pa (p max 1,409 Pa); no probe digit
  // differs at np = 1, 2, 4. Bounds about ten times those.
  constexpr double c2_rho = 20.0 * 20.0 * 1000.0;
  check_against_one_process(std::string(FSI_TEST_DATA) + "/dam_break_ranks_3d.yaml", 11,
                            {1e-15, 2.5e-13, 2.5e-14 * c2_rho});
}

TEST_CASE("mpirun -np N fsi run of an SPH scene gives the one-process files", "[mpi]") {
  // data/dam_break_ranks_sph.yaml: 3,000 particles, t = 0 and every ms of 16 (256 acoustic
  // steps). Round-off of pair sums in another order (the ghosts' places in the pair lists): the
  // density differs by 2.4e-12 kg/m^3 (2e-15 relative) after the first ms, then grows about
  // twofold a ms. Measured over the 17 frames at np = 2, 3, 4: |dx| <= 1.5e-13 m, |dv| <= 5.5e-11
  // m/s, |dp| <= 1.2e-6 Pa (p max 3,268 Pa); no probe digit differs at np = 1, 2, 3, 4. Bounds
  // about ten times those.
  check_against_one_process(std::string(FSI_TEST_DATA) + "/dam_break_ranks_sph.yaml", 17,
                            {1.5e-12, 5.5e-10, 1.2e-5}, {1, 2, 3, 4});
}

TEST_CASE("mpirun -np N fsi run of a 3-D SPH scene gives the one-process files", "[mpi]") {
  // data/dam_break_ranks_sph_3d.yaml: 1,600 particles, t = 0 and every 6 ms of 60 (211 acoustic
  // steps). Measured at np = 2, 4: |dx| <= 4.8e-14 m, |dv| <= 1.5e-10 m/s, |dp| <= 1.2e-6 Pa (p
  // max 13,649 Pa); probes within 8.2e-11 of their largest values (a last digit at np = 4). Bounds
  // about ten times those.
  check_against_one_process(std::string(FSI_TEST_DATA) + "/dam_break_ranks_sph_3d.yaml", 11,
                            {5e-13, 1.5e-9, 1.2e-5});
}

TEST_CASE("bad input under mpirun: exit 2, the message once", "[mpi]") {
  const fs::path out = scratch() / "fsi_ranks_bad";
  fs::remove_all(out);
  const std::string data = std::string(FSI_SOURCE_DIR) + "/tests/apps/data/";
  const Outcome bad = fsi(2, "run " + data + "bad_density.yaml --out " + out.string());
  INFO(bad.output);
  CHECK(bad.status == 2);
  CHECK(occurrences(bad.output, "bad_density.yaml:") == 1);
  // A periodic SPH fluid (the inflow channel): refused once.
  const Outcome periodic =
      fsi(2, "run " + std::string(FSI_SOURCE_DIR) +
                 "/data/scenes/poiseuille_channel_sph.yaml --out " + out.string());
  INFO(periodic.output);
  CHECK(periodic.status == 2);
  // FILE:LINE: key: what, the line of the key that makes it periodic (inflow, line 35).
  CHECK(occurrences(periodic.output, "poiseuille_channel_sph.yaml:35: fluid.inflow: not yet "
                                     "supported under mpirun") == 1);
  CHECK(occurrences(periodic.output, "a periodic fluid cannot be decomposed") == 1);
  CHECK(!fs::exists(out / "fields.h5")); // refused before any computation
  // The 3-D slab periodic along z: the same at periodic_z's line.
  const Outcome slab = fsi(2, "run " + std::string(FSI_SOURCE_DIR) +
                                  "/data/scenes/dam_break_slab_sph_3d.yaml --out " + out.string());
  INFO(slab.output);
  CHECK(slab.status == 2);
  CHECK(occurrences(slab.output, "dam_break_slab_sph_3d.yaml:26: fluid.periodic_z: not yet "
                                 "supported under mpirun") == 1);
  CHECK(!fs::exists(out / "fields.h5"));
  // The periodic EMPS slab: the same at its periodic_z line (30).
  const Outcome emps =
      fsi(2, "run " + std::string(FSI_SOURCE_DIR) +
                 "/data/scenes/dam_break_slab_emps_3d_periodic.yaml --out " + out.string());
  INFO(emps.output);
  CHECK(emps.status == 2);
  CHECK(occurrences(emps.output, "dam_break_slab_emps_3d_periodic.yaml:30: fluid.periodic_z: not "
                                 "yet supported under mpirun") == 1);
  CHECK(!fs::exists(out / "fields.h5"));
}

TEST_CASE("a 3-D fluid behind a wall under mpirun: one process's message, once", "[mpi]") {
  // Each rank queries the walls for its block of the fill only (validate3); the fill, 12 layers
  // in z, reaches 0.04 m past the STL tank's face z = 0.2: the first particle behind it in id
  // order (z = 0.21, layer 10) is in the last rank's block at np = 2 and 3, and its message is
  // the one-process message, printed once.
  const fs::path out = scratch() / "fsi_ranks_behind";
  const std::string args = "run " + std::string(FSI_SOURCE_DIR) +
                           "/data/scenes/hydrostatic_tank_emps_3d_stl.yaml --out " + out.string() +
                           " --overwrite --set 'fluid.regions[0].max=[0.2, 0.2, 0.24]'";
  const std::string message = "fluid.tank_file: " + std::string(FSI_SOURCE_DIR) +
                              "/data/scenes/../meshes/hydrostatic_tank_emps_3d.stl: the fluid at "
                              "(0.01, 0.01, 0.21) m lies behind facet 12 (each facet's normal "
                              "must point into the fluid)";
  const Outcome one = fsi(0, args);
  INFO(one.output);
  CHECK(one.status == 2);
  CHECK(occurrences(one.output, message) == 1);
  for (const int np : {2, 3}) {
    const Outcome o = fsi(np, args, 120); // a rank left out of the verdict would wait forever
    INFO(o.output);
    CHECK(o.status == 2);
    CHECK(occurrences(o.output, message) == 1);
    CHECK(occurrences(o.output, "(rank ") == 0);
  }
  CHECK(!fs::exists(out / "fields.h5"));
}

namespace {

/// A 2-D EMPS state file's particles (fluid/: x, y, vx, vy) in id order, row after row.
std::vector<double> particles_by_id(const fs::path& h5) {
  const std::vector<double> id = dataset(h5, "fluid/id");
  std::vector<std::vector<double>> columns;
  for (const char* name : {"fluid/x", "fluid/y", "fluid/vx", "fluid/vy"})
    columns.push_back(dataset(h5, name));
  std::vector<std::size_t> order(id.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return id[a] < id[b]; });
  std::vector<double> rows;
  for (const std::size_t i : order)
    for (const auto& column : columns) rows.push_back(column[i]);
  return rows;
}

} // namespace

TEST_CASE("a run failing on some ranks stops every rank as one process does", "[mpi]") {
  // data/one_rank_failure.yaml: a column's particles thrown behind the floor at step 2 on the
  // ranks that hold it; the other column's ranks find nothing (the scene's comment).
  const std::string failing = std::string(FSI_TEST_DATA) + "/one_rank_failure.yaml";
  const std::string what = "is behind wall segment";
  std::vector<double> one_process; // failed_state.h5's particles of the plain run, by id
  for (const int np : {0, 2, 4}) {
    const fs::path out = scratch() / ("fsi_rank_failure_np" + std::to_string(np));
    fs::remove_all(out);
    const Outcome o = fsi(np, "run " + failing + " --out " + out.string() + " --threads 1", 240);
    INFO("np = " << np << ":\n" << o.output);
    CHECK(o.status == 3); // not 124 (a hang killed), not an abort's
    CHECK(occurrences(o.output, what) == 1);
    CHECK(occurrences(o.output, "step 2, t = 0.008 s") == 1);
    CHECK(occurrences(o.output, "MPI_ABORT") == 0);
    // The message says where: the failing rank (under mpirun), never one that found nothing.
    if (np > 0) {
      CHECK(occurrences(o.output, " of " + std::to_string(np) + ")") == 1);
      CHECK(occurrences(o.output, "(on another process)") == 0);
    }
    if (np == 2) // the failing column's rank, not rank 0 that writes the files
      CHECK(occurrences(o.output, "(rank 1 of 2)") == 1);
    const std::string json = text_of(out / "run.json");
    INFO(json);
    CHECK(occurrences(json, "\"status\": \"failed\"") == 1);
    CHECK(occurrences(json, what) == 1);
    // probes.csv: the header, t = 0, the frame after step 1 and the failed step's last state.
    const auto rows = probes(out);
    REQUIRE(rows.size() == 3);
    CHECK(rows[1][0] == Approx(4e-3));
    CHECK(rows[2][0] == Approx(8e-3));
    CHECK(frames(out) == 3);
    // failed_state.h5, the failed step's state in the one-process format (gathered to rank 0
    // under mpirun): named in the message, flagged failed, at the failed step's end, and its
    // particles those of the plain run to round-off.
    const fs::path state = out / "failed_state.h5";
    REQUIRE(fs::exists(state));
    CHECK(occurrences(o.output, state.string()) == 1);
    CHECK(dataset(state, "driver/failed") == std::vector<double>{1.0});
    CHECK(dataset(state, "driver/time") == std::vector<double>{8e-3});
    const std::vector<double> particles = particles_by_id(state);
    if (np == 0) {
      one_process = particles;
      CHECK(particles.size() == 4 * 2500);
      continue;
    }
    const double difference = max_difference(particles, one_process) / max_abs(one_process);
    std::printf("one_rank_failure np=%d: failed_state.h5 particles %.2e of the largest |value| "
                "from one process's\n",
                np, difference);
    CHECK(difference <= 5e-14); // measured 4.2e-15 (np = 2), 4.9e-15 (np = 4)
  }
}

namespace {

/// `fsi run` of dam_break_ranks.yaml on `np` ranks (0: without mpirun) with `args` (overrides,
/// --restart) into `out`, which it keeps.
void run_into(int np, const fs::path& out, const std::string& args) {
  const Outcome o = fsi(np, "run " + dam_break + " --out " + out.string() + " --threads 1 " + args);
  INFO("np = " << np << ": " << o.output);
  REQUIRE(o.status == 0);
}

/// A fresh copy of `from` (a run's folder) at `to`.
fs::path copy_of(const fs::path& from, const std::string& to) {
  const fs::path out = scratch() / to;
  fs::remove_all(out);
  fs::copy(from, out);
  return out;
}

} // namespace

TEST_CASE("a checkpoint of a decomposed run restarts on any process count", "[mpi]") {
  // 20 steps, a checkpoint after 10 (and one at the end); the restarts continue from step 10.
  const std::string set = "--set time.end=0.002 --set checkpoint.interval_steps=10";
  const std::string ten = "/checkpoint_000000010.h5";
  const fs::path four = scratch() / "fsi_ckpt_np4";
  fs::remove_all(four);
  run_into(4, four, set);
  REQUIRE(fs::exists(four / ten.substr(1)));
  // An np = 4 checkpoint continued on 4 and 2 ranks and by plain fsi (the one-process format);
  // a one-process checkpoint continued on 2 ranks.
  const fs::path serial = scratch() / "fsi_ckpt_np0";
  fs::remove_all(serial);
  run_into(0, serial, set);
  struct Case {
    int np;
    fs::path reference, out; // fields compared entry by entry when both are in id order
  };
  std::vector<Case> cases;
  for (const int np : {4, 2, 0}) {
    const fs::path out = copy_of(four, "fsi_ckpt_np4_on" + std::to_string(np));
    run_into(np, out, set + " --restart " + out.string() + ten);
    cases.push_back({np, four, out});
  }
  const fs::path on2 = copy_of(serial, "fsi_ckpt_np0_on2");
  run_into(2, on2, set + " --restart " + on2.string() + ten);
  cases.push_back({2, serial, on2});
  for (const Case& k : cases) {
    // Frames 5 (the checkpoint's) to 10: the continued run against the uninterrupted one, entry
    // by entry in id order; probes.csv row by row.
    REQUIRE(frames(k.out) == 11);
    const auto a = probes(k.out), b = probes(k.reference);
    REQUIRE(a.size() == b.size());
    double worst = 0.0;
    for (std::size_t c = 1; c < b[0].size(); ++c) {
      std::vector<double> x, y;
      for (std::size_t r = 5; r < b.size(); ++r) x.push_back(a[r][c]), y.push_back(b[r][c]);
      worst = std::max(worst, max_difference(x, y) / max_abs(y));
    }
    double dx = 0, dv = 0, dp = 0;
    // A one-process fields.h5 holds the particles in its cell order: probes only.
    for (int f = 5; f <= 10 && k.reference == four; ++f) {
      dx = std::max(dx,
                    max_difference(field(k.out, f, "position"), field(k.reference, f, "position")));
      dv = std::max(dv,
                    max_difference(field(k.out, f, "velocity"), field(k.reference, f, "velocity")));
      dp = std::max(dp,
                    max_difference(field(k.out, f, "pressure"), field(k.reference, f, "pressure")));
    }
    std::printf("restart of %s on np=%d: probes max relative difference %.2e; fields (np = 4 "
                "reference only): |dx| "
                "%.2e m, |dv| %.2e m/s, |dp| %.2e Pa\n",
                k.reference.filename().c_str(), k.np, worst, dx, dv, dp);
    CHECK(occurrences(text_of(k.out / "run.json"), "\"status\": \"completed\"") == 1);
    // The bounds of the first test case: round-off of pair sums in another order.
    constexpr double c2_rho = 20.0 * 20.0 * 1000.0;
    CHECK(worst <= 1e-9);
    CHECK(dx <= 1e-15);
    CHECK(dv <= 1e-12);
    CHECK(dp <= 1e-13 * c2_rho);
  }
  // The files of an np = 4 run: one checkpoint a step, no other rank's.
  std::size_t checkpoints = 0;
  for (const auto& e : fs::directory_iterator(four))
    checkpoints += e.path().filename().string().rfind("checkpoint_", 0) == 0;
  CHECK(checkpoints == 2);
}

TEST_CASE("a checkpoint with fewer particles than processes is refused once", "[mpi]") {
  // Two particles (a 4 mm x 2 mm region at l0 = 2 mm), checkpointed by one process after a step.
  const std::string set = "--set time.end=1e-4 --set output.interval=1e-4 "
                          "--set checkpoint.interval_steps=1 "
                          "--set 'fluid.regions[0].max=[0.004, 0.002]'";
  const fs::path out = scratch() / "fsi_ckpt_tiny";
  fs::remove_all(out);
  run_into(0, out, set);
  const std::string checkpoint = (out / "checkpoint_000000001.h5").string();
  const Outcome o = fsi(4, "run " + dam_break + " --out " + out.string() + " --threads 1 " + set +
                               " --restart " + checkpoint);
  INFO(o.output);
  CHECK(o.status == 2);
  CHECK(occurrences(o.output, checkpoint + ": fluid: 2 particles for 4 processes") == 1);
}

namespace {

const std::string walhorn = std::string(FSI_TEST_DATA) + "/walhorn_ranks.yaml";

/// A run's interface.h5 dataset (one row a step: the interface motion the fluid used, the loads
/// the structure took); "displacement": the positions less the first row's.
std::vector<double> history(const fs::path& out, const std::string& name) {
  const fs::path h5 = out / "interface.h5";
  if (name != "displacement") return dataset(h5, name);
  std::vector<double> x = dataset(h5, "position");
  const std::size_t row = x.size() / dataset(h5, "time").size();
  for (std::size_t i = x.size(); i-- > row;) x[i] -= x[i % row];
  std::fill(x.begin(), x.begin() + static_cast<std::ptrdiff_t>(row), 0.0);
  return x;
}

/// The largest |a - b| of two runs' history(name) relative to the largest |b|.
double relative_history(const fs::path& a, const fs::path& b, const std::string& name) {
  const auto x = history(a, name), y = history(b, name);
  return max_difference(x, y) / max_abs(y);
}

/// The iterations column of coupling.csv, one entry a step.
std::vector<int> iterations(const fs::path& out) {
  std::ifstream in(out / "coupling.csv");
  std::string line, cell;
  std::getline(in, line);
  std::vector<int> counts;
  while (std::getline(in, line)) {
    std::stringstream cells(line);
    for (int k = 0; k <= 3; ++k) std::getline(cells, cell, ',');
    counts.push_back(std::stoi(cell));
  }
  return counts;
}

/// A run's interface loads summed over the nodes, per step and component (`dimension` of them,
/// interleaved in each step's row as in interface.h5).
std::vector<double> total_loads(const fs::path& out, std::size_t dimension) {
  const std::vector<double> f = history(out, "load");
  const std::size_t steps = dataset(out / "interface.h5", "time").size(), row = f.size() / steps;
  std::vector<double> total(steps * dimension, 0.0);
  for (std::size_t i = 0; i < f.size(); ++i) total[(i / row) * dimension + i % dimension] += f[i];
  return total;
}

/// probes.csv of two runs: the largest difference of each probe relative to its largest |value|.
double relative_probes(const fs::path& a, const fs::path& b, std::size_t first_row = 0) {
  const auto x = probes(a), y = probes(b);
  if (x.size() != y.size()) return INFINITY;
  double worst = 0.0;
  for (std::size_t c = 1; c < y[0].size(); ++c) {
    std::vector<double> u, w;
    for (std::size_t r = first_row; r < y.size(); ++r) u.push_back(x[r][c]), w.push_back(y[r][c]);
    worst = std::max(worst, max_difference(u, w) / max_abs(w));
  }
  return worst;
}

/// `scene` with `args` (overrides) by plain fsi and under mpirun at np = 1 and `nps`, recording
/// interface.h5: np = 1 gives the one-process probes.csv and interface loads and motion bitwise
/// (the loads' sum over one rank is the identity), the others the loads, interface
/// displacements and velocities of every step within `bound` of their largest values, and the
/// loads' sum over the nodes (the force on the structure) within 1e-10 of its largest. The
/// one-process run writes `rows` probe rows and loads the structure above `load` somewhere and
/// moves it above `moved`.
struct Coupled {
  std::size_t rows;
  double load, moved;
  std::size_t dimension;
};
void check_coupled(const std::string& scene, const std::string& args, const Coupled& expect,
                   double bound, std::initializer_list<int> nps = {2, 4}) {
  const std::string set = args + " --set coupling.record_interface=true";
  const fs::path serial = run(scene, 0, set), one = run(scene, 1, set);
  REQUIRE(probes(serial).size() == expect.rows);
  CHECK(text_of(one / "probes.csv") == text_of(serial / "probes.csv"));
  CHECK(relative_history(one, serial, "load") == 0.0);
  CHECK(relative_history(one, serial, "displacement") == 0.0);
  CHECK(max_abs(history(serial, "load")) > expect.load);
  CHECK(max_abs(history(serial, "displacement")) > expect.moved);
  for (const int np : nps) {
    const fs::path out = run(scene, np, set);
    const double loads = relative_history(out, serial, "load"),
                 motion = relative_history(out, serial, "displacement"),
                 velocity = relative_history(out, serial, "velocity"),
                 digits = relative_probes(out, serial);
    const auto reference = total_loads(serial, expect.dimension);
    const double total =
        max_difference(total_loads(out, expect.dimension), reference) / max_abs(reference);
    std::printf("%s np=%d against one process: loads %.2e, interface displacements %.2e, "
                "velocities %.2e (relative to the largest), total load %.2e; probes %.2e\n",
                fs::path(scene).stem().c_str(), np, loads, motion, velocity, total, digits);
    CHECK(total <= 1e-10);
    CHECK(loads <= bound);
    CHECK(motion <= bound);
    CHECK(velocity <= bound);
    CHECK(digits <= 1e-9); // 10 printed digits
    CHECK(occurrences(text_of(out / "run.json"), "\"status\": \"completed\"") == 1);
  }
}

/// The plate of hydrostatic_plate_3d(_emps) as 3 x 1 x 3 T10 cells (10 x 2 x 10 in the scenes,
/// whose solve is most of their step) and l0 = 0.1 m (500 particles).
const std::string coarse_plate =
    "--set fluid.l0=0.1 --set structures[0].mesh.elements_x=3 "
    "--set structures[0].mesh.elements_y=1 --set structures[0].mesh.elements_z=3";

} // namespace

TEST_CASE("mpirun -np N fsi run of a coupled scene gives the one-process answer", "[mpi]") {
  // Walhorn coarse's fluid and obstacle (css), 200 steps: the obstacle solved on rank 0, the
  // loads of every rank's particles summed. interface.h5 holds every step's interface motion and
  // loads to 17 digits; probes.csv (corner_x, wall_force_x|y) 10 digits. The column loads the
  // obstacle (N/m) and moves it (m).
  check_coupled(walhorn, "", {21, 0.1, 1e-10, 2}, 1e-10, {2, 3, 4});
}

TEST_CASE("mpirun -np N fsi run of a 3-D EMPS scene with a T10 plate", "[mpi]") {
  // hydrostatic_plate_3d_emps coarsened (coarse_plate, css), 200 steps: the plate solved on
  // rank 0, the nodal loads (eq. 59) of every rank's particles summed. The column is moved off
  // the scene's lattice (region from x = 13 mm, z = 7 mm: 405 particles): on it, the particles
  // of the plate's edges lie exactly as far from the plate as from a side wall, and round-off
  // decides which face takes their edge image (split_corner_term), a jump of 4e-8 of the
  // largest nodal load at np = 2 and 4 (8.2e-7 after 200 steps, the total load to 1e-14, the
  // probes equal), not a difference of the ranks' sums.
  check_coupled(std::string(FSI_SOURCE_DIR) + "/data/scenes/hydrostatic_plate_3d_emps.yaml",
                "--set time.end=0.16 --set output.interval=0.016 " + coarse_plate +
                    " --set 'fluid.regions[0].min=[0.013, 0.0, 0.007]'",
                {11, 1.0, 1e-7, 3}, 1e-10);
}

TEST_CASE("mpirun -np N fsi run of an SPH fluid with structures", "[mpi]") {
  // The tracked wall forces of every rank's particles summed into the loads, the boundary points
  // moved alike on every rank. 2-D: tiny_coupled_sph (the column against the obstacle from the
  // first step, css), 200 steps; 3-D: hydrostatic_plate_3d coarsened (coarse_plate, css), 100.
  check_coupled(std::string(FSI_SOURCE_DIR) + "/tests/apps/data/tiny_coupled_sph.yaml",
                "--set time.end=0.004 --set output.interval=0.0004", {11, 1.0, 1e-9, 2}, 1e-10);
  check_coupled(std::string(FSI_SOURCE_DIR) + "/data/scenes/hydrostatic_plate_3d.yaml",
                "--set time.end=0.1 --set output.interval=0.01 " + coarse_plate, {11, 1.0, 1e-7, 3},
                1e-10);
}

namespace {

/// `scene` with `args` under bgs with IQN-ILS and with Aitken, `steps` coupling steps, by plain
/// fsi and under mpirun at each of `nps`: every rank's scheme works on the same summed loads and
/// broadcast motion, so it converges in the same iterations; the interface loads and
/// displacements of every step within 1e-10 of their largest values (np = 1: bitwise).
void check_implicit(const std::string& scene, const std::string& args, std::size_t steps,
                    std::initializer_list<int> nps) {
  for (const std::string acceleration : {"iqn-ils", "aitken"}) {
    const std::string set =
        args + " --set coupling.scheme=bgs --set coupling.acceleration=" + acceleration +
        " --set coupling.record_interface=true";
    const fs::path serial = run(scene, 0, set, acceleration);
    const auto counts = iterations(serial);
    REQUIRE(counts.size() == steps);
    CHECK(*std::max_element(counts.begin(), counts.end()) > 2); // iterated
    for (const int np : nps) {
      const fs::path out = run(scene, np, set, acceleration);
      const double loads = relative_history(out, serial, "load"),
                   motion = relative_history(out, serial, "displacement");
      std::printf("%s bgs %s np=%d: iterations %s, loads %.2e, interface displacements %.2e "
                  "against one process\n",
                  fs::path(scene).stem().c_str(), acceleration.c_str(), np,
                  iterations(out) == counts ? "equal" : "DIFFER", loads, motion);
      CHECK(iterations(out) == counts);
      CHECK(loads <= (np == 1 ? 0.0 : 1e-10));
      CHECK(motion <= (np == 1 ? 0.0 : 1e-10));
      CHECK(relative_probes(out, serial) <= (np == 1 ? 0.0 : 1e-9));
    }
  }
}

} // namespace

TEST_CASE("an implicit coupling scheme under mpirun iterates as one process", "[mpi]") {
  // tests/apps/data/hydrostatic_plate_small.yaml with bgs, 30 steps.
  check_implicit(std::string(FSI_SOURCE_DIR) + "/tests/apps/data/hydrostatic_plate_small.yaml",
                 "--set time.end=0.003 --set output.interval=0.001", 30, {2, 4});
}

TEST_CASE("an implicit coupling scheme with an SPH fluid under mpirun iterates as one process",
          "[mpi]") {
  // tiny_coupled_sph with bgs, 100 steps of 2e-5 s (advection steps rebuilt within them): each
  // iteration restores the decomposed fluid's owned particles and remakes its halo.
  check_implicit(std::string(FSI_SOURCE_DIR) + "/tests/apps/data/tiny_coupled_sph.yaml",
                 "--set time.end=0.002 --set output.interval=0.0002", 100, {1, 2, 4});
}

TEST_CASE("a coupled checkpoint at np = 4 continues on 2 ranks", "[mpi]") {
  // walhorn_ranks.yaml, 200 steps, checkpoints every 100: the np = 4 checkpoint of step 100
  // (written by rank 0, the obstacle's state from rank 0, which solves it) on 2 ranks.
  const std::string set = "--set checkpoint.interval_steps=100";
  const fs::path four = run(walhorn, 4, set, "_ckpt");
  const std::string hundred = "checkpoint_000000100.h5";
  REQUIRE(fs::exists(four / hundred));
  const fs::path out = copy_of(four, "walhorn_ckpt_np4_on2");
  const Outcome o = fsi(2, "run " + walhorn + " --out " + out.string() + " --threads 1 " + set +
                               " --restart " + (out / hundred).string());
  INFO(o.output);
  REQUIRE(o.status == 0);
  // Frames 10 (the checkpoint's) to 20; the obstacle's displacement field to 17 digits.
  double worst = 0.0, largest = 0.0;
  for (int f = 10; f <= 20; ++f) {
    const auto a = field(out, f, "displacement", "obstacle"),
               b = field(four, f, "displacement", "obstacle");
    worst = std::max(worst, max_difference(a, b));
    largest = std::max(largest, max_abs(b));
  }
  std::printf("walhorn_ranks checkpoint of np=4 on np=2: obstacle displacement %.2e relative, "
              "probes %.2e\n",
              worst / largest, relative_probes(out, four, 10));
  CHECK(largest > 0.0);
  CHECK(worst <= 1e-10 * largest);
  CHECK(relative_probes(out, four, 10) <= 1e-9);
}

TEST_CASE("a structure failing on rank 0 stops every rank as one process does", "[mpi]") {
  // walhorn_ranks.yaml with an obstacle of E = 0.01 Pa and dt = 1 ms: its elements invert at
  // structure step 3. Rank 0 solves it; the failure travels with the motion's broadcast, so no
  // rank waits for it: exit 3 on every rank, rank 0's message once, run.json "failed".
  const std::string set = "--set structures[0].material.youngs_modulus=0.01 --set time.dt=1e-3 "
                          "--set time.end=0.05 --set output.interval=1e-3";
  const fs::path serial = scratch() / "walhorn_failure_np0",
                 two = scratch() / "walhorn_failure_np2";
  for (const auto& out : {serial, two}) fs::remove_all(out);
  const Outcome one = fsi(0, "run " + walhorn + " --out " + serial.string() + " " + set);
  const Outcome o = fsi(2, "run " + walhorn + " --out " + two.string() + " " + set, 120);
  INFO(o.output);
  CHECK(one.status == 3);
  CHECK(o.status == 3);
  const std::string what = "structure 'obstacle': element 2: det F = ";
  CHECK(occurrences(one.output, what) == 1);
  CHECK(occurrences(o.output, what) == 1);
  CHECK(occurrences(o.output, "(structure step 3, t = 0.003)") == 1);
  CHECK(occurrences(text_of(two / "run.json"), "\"status\": \"failed\"") == 1);
  CHECK(frames(two) == 4); // t = 0 to the last step, 3 ms
}

TEST_CASE("an SPH checkpoint under mpirun restarts on any process count", "[mpi]") {
  // The one-process format written by rank 0: dam_break_ranks_sph.yaml's step-20 checkpoint of
  // an np = 4 run continued on 2 ranks and by plain fsi, a plain run's on 2; tiny_coupled_sph's
  // (the obstacle from rank 0, the tracked walls' viscous force summed) of an np = 2 run on 4
  // ranks. probes.csv against the uninterrupted run.
  struct Case {
    std::string scene, set;
    int np;
    std::vector<int> on;
  };
  const std::vector<Case> cases{
      {std::string(FSI_TEST_DATA) + "/dam_break_ranks_sph.yaml", "", 4, {2, 0}},
      {std::string(FSI_TEST_DATA) + "/dam_break_ranks_sph.yaml", "", 0, {2}},
      {std::string(FSI_SOURCE_DIR) + "/tests/apps/data/tiny_coupled_sph.yaml",
       "--set time.end=0.002 --set output.interval=0.0002",
       2,
       {4}}};
  for (const Case& k : cases) {
    const std::string set = k.set + " --set checkpoint.interval_steps=20 --set checkpoint.keep=10";
    const fs::path whole = run(k.scene, k.np, set, "_ckpt");
    const std::string twenty = "checkpoint_000000020.h5";
    REQUIRE(fs::exists(whole / twenty));
    for (const int np : k.on) {
      const fs::path out = copy_of(whole, fs::path(k.scene).stem().string() + "_ckpt" +
                                              std::to_string(k.np) + "_on" + std::to_string(np));
      const Outcome o = fsi(np, "run " + k.scene + " --out " + out.string() + " --threads 1 " +
                                    set + " --restart " + (out / twenty).string());
      INFO(o.output);
      REQUIRE(o.status == 0);
      const double digits = relative_probes(out, whole);
      std::printf("%s checkpoint of np=%d continued on np=%d: probes %.2e\n",
                  fs::path(k.scene).stem().c_str(), k.np, np, digits);
      const std::string json = text_of(out / "run.json");
      CHECK(occurrences(json, "\"status\": \"completed\"") == 1);
      CHECK(occurrences(json, twenty) == 1); // restarted_from
      CHECK(digits <= 1e-9);                 // 10 printed digits
    }
  }
}

TEST_CASE("fields.h5 written collectively at np = 1 is the one-process file", "[mpi]") {
  // Every rank writes its own rows at their ids' places (parallel HDF5, apps/src/output/
  // dataset_part.cpp); at np = 1 the decomposed fluid steps bitwise as one process does, so every
  // frame holds the same rows, bit for bit, as a plain `fsi run` (whose rows are in its cell
  // order: compared sorted). The np = 2, 4 files against np = 1 are the cases above.
  struct Case {
    std::string scene;
    std::vector<std::string> names; // position and the scene's output.fields
  };
  const std::vector<std::string> emps{"position", "velocity", "pressure", "pnd", "free_surface"};
  const std::string data = std::string(FSI_TEST_DATA) + "/";
  for (const Case& c : {Case{dam_break, emps}, Case{data + "dam_break_ranks_3d.yaml", emps},
                        Case{data + "dam_break_ranks_sph.yaml",
                             {"position", "velocity", "pressure", "density", "wkgc_indicator"}},
                        Case{data + "dam_break_ranks_sph_3d.yaml",
                             {"position", "velocity", "pressure", "density"}}}) {
    INFO(c.scene);
    const fs::path serial = run(c.scene, 0, "", "_rows"), one = run(c.scene, 1, "", "_rows");
    CHECK(text_of(one / "fields.xmf") == text_of(serial / "fields.xmf")); // the same datasets
    REQUIRE(frames(one) == frames(serial));
    for (int f = 0; f < frames(one); ++f) {
      const auto a = sorted_rows(one, f, c.names), b = sorted_rows(serial, f, c.names);
      CHECK(a.size() > 100);
      CHECK(a == b);
    }
  }
  // Particles removed (the domain's side at the column's: 68 of 3,000 leave by t = 0.03 s): the
  // rows' places counted on the table of the ids present. Measured at np = 2: |dx| 3.6e-15 m,
  // |dv| 2.8e-12 m/s, |dp| 1.0e-8 Pa against np = 1 (the file of main's gather at np = 2 equal
  // bit for bit); bounds about ten times those.
  const std::string leave =
      "--set 'fluid.domain.max=[0.1001, 0.3]' --set time.end=0.03 --set output.interval=0.003";
  const fs::path left1 = run(dam_break, 1, leave, "_leave"),
                 left2 = run(dam_break, 2, leave, "_leave");
  CHECK(occurrences(text_of(left2 / "run.json"), "\"removed_particles\": 68") == 1);
  REQUIRE(frames(left2) == frames(left1));
  for (int f = 0; f < frames(left1); ++f) {
    CHECK(max_difference(field(left2, f, "position"), field(left1, f, "position")) <= 4e-14);
    CHECK(max_difference(field(left2, f, "velocity"), field(left1, f, "velocity")) <= 3e-11);
    CHECK(max_difference(field(left2, f, "pressure"), field(left1, f, "pressure")) <= 1e-7);
  }
  CHECK(field(left1, frames(left1) - 1, "pressure").size() == 2932);
  // A file written by 2 ranks opens with h5py (the reader of scripts/) as one process's does.
  const fs::path two = run(dam_break, 2, "", "_rows");
  const std::string check =
      "/usr/bin/python3 -c \"import h5py, sys; f = h5py.File(sys.argv[1], 'r'); "
      "n = len(f['frames']); p = f['frames/%d/particles/position' % (n - 1)]; "
      "sys.exit(0 if n == 21 and p.shape[1] == 2 and p.shape[0] > 100 else 1)\" " +
      (two / "fields.h5").string();
  CHECK(std::system(check.c_str()) == 0);
}

TEST_CASE("fields.h5 failing on one rank stops every rank with its message", "[mpi]") {
  // Rank 1 alone may write 358,400 bytes (RLIMIT_FSIZE: sh's `ulimit -f 700`, 512-byte blocks;
  // SIGXFSZ ignored; MPI over TCP, whose shared-memory files the limit would break): frame 0
  // (fields.h5 207,032 bytes) fits, and rank 1's block of frame 1's free_surface, bytes 365,080
  // to 377,080, does not (EFBIG); the room check before frame 1 passes (it knows a frame's size
  // from frame 2 on). The failure is agreed after the dataset (apps' agreed): every rank stops
  // there, exit 3, rank 1's message once; fields.xmf names frame 0, the one-process frame 0.
  const fs::path out = scratch() / "fsi_write_failure_np2";
  fs::remove_all(out);
  const fs::path script = scratch() / "fsi_write_failure.sh",
                 log = scratch() / "fsi_write_failure.txt";
  std::ofstream(script)
      << "if [ \"$OMPI_COMM_WORLD_RANK\" = 1 ]; then trap '' XFSZ; ulimit -f 700; "
         "fi\nexec "
      << FSI_EXE << " run " << dam_break << " --out " << out.string() << " --threads 1\n";
  const std::string command = "timeout -k 10 240 " + std::string(FSI_MPIEXEC) +
                              " --oversubscribe --allow-run-as-root --mca btl self,tcp -np 2 sh " +
                              script.string() + " > " + log.string() + " 2>&1";
  const int raw = std::system(command.c_str());
  const std::string output = text_of(log);
  INFO(output);
  CHECK((WIFEXITED(raw) ? WEXITSTATUS(raw) : -1) == 3); // not 124 (a hang), not an abort's
  CHECK(occurrences(output, "fields.h5: cannot write dataset free_surface (rank 1 of 2)") == 1);
  CHECK(occurrences(output, "(rank 1 of 2)") == 1);
  CHECK(occurrences(output, "MPI_ABORT") == 0);
  const std::string json = text_of(out / "run.json");
  CHECK(occurrences(json, "\"status\": \"failed\"") == 1);
  CHECK(occurrences(json, "(rank 1 of 2)") == 1);
  // The index names frame 0 alone, and frame 0 is the plain run's: positions and flags exact,
  // pnd and p to round-off (the initial pressures are summed over the ranks since each builds
  // its block of the fill: measured 1e-10 Pa, one unit of the file's last digit).
  const std::string xmf = text_of(out / "fields.xmf");
  CHECK(occurrences(xmf, "<Time ") == 1);
  const std::vector<std::string> exact{"position", "velocity", "free_surface"};
  const fs::path serial = run(dam_break, 0, "--set time.end=2e-4", "_first");
  CHECK(sorted_rows(out, 0, exact) == sorted_rows(serial, 0, exact));
  // Scales: pnd's largest value; p's c^2 rho = 4e5 Pa (p = c^2 rho (pnd - n0) / n0, 0 at rest).
  for (const auto& [name, scale] :
       {std::pair<std::string, double>{"pnd", 0.0}, {"pressure", 4e5}}) {
    std::vector<double> a, b;
    for (const auto& r : sorted_rows(out, 0, {"position", name})) a.push_back(r.back());
    for (const auto& r : sorted_rows(serial, 0, {"position", name})) b.push_back(r.back());
    CHECK(max_difference(a, b) <= 1e-12 * (scale > 0.0 ? scale : max_abs(b)));
  }
}
