// Output under faults (issue 17): a full disk, simulated by RLIMIT_FSIZE with SIGXFSZ ignored (a
// write past the limit fails with EFBIG, as one on a full disk fails with ENOSPC), stops a run
// with exit status 3 and its message, keeps every earlier frame readable, leaves no temporary
// file and no truncated run.json, and never crashes in HDF5's exit handler; a checkpoint with a
// changed value or a NaN is refused naming the dataset; a checkpoint of a Courant-stepped run
// says so.
#include "fsi/core/error.hpp"
#include "fsi_app/output/checkpoint_file.hpp"
#include "fsi_app/output/fields_file.hpp"
#include "fsi_process.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <csignal>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <hdf5.h>
#include <limits>
#include <regex>
#include <sstream>
#include <sys/file.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;
using Catch::Contains;
using Catch::StartsWith;
using fsi_test::slurp;
using fsi_test::wait_status;

namespace {

const std::string fluid = FSI_TEST_DATA "/tiny_fluid.yaml";

fs::path fresh(const std::string& name) {
  return fsi_test::fresh_dir("output", name);
}

/// Limits every file the calling process writes to `bytes` and makes a write past it fail with
/// EFBIG instead of killing the process (what a full disk does with ENOSPC).
void limit_file_size(rlim_t bytes) {
  std::signal(SIGXFSZ, SIG_IGN);
  const struct rlimit limit = {bytes, bytes};
  setrlimit(RLIMIT_FSIZE, &limit);
}

/// Runs `fsi ARGS...` to its end, with files limited to `limit` bytes (0: no limit); stderr in
/// `err`.
int run_fsi(const std::vector<std::string>& args, const fs::path& logs, rlim_t limit,
            std::string& err) {
  const int status = wait_status(fsi_test::spawn(FSI_EXECUTABLE, args, logs, [limit] {
    if (limit > 0) limit_file_size(limit);
  }));
  err = slurp(logs / "stderr.txt");
  return status;
}

/// A fresh folder DIR (returned) with the fluid scene run to t = 0.004 s in DIR/run: its
/// checkpoint at step 50 is DIR/run/checkpoint_000000050.h5.
fs::path checkpointed_run(const std::string& name) {
  const fs::path dir = fresh(name);
  std::string err;
  REQUIRE(run_fsi({"run", fluid, "--out", (dir / "run").string(), "--set", "time.end=0.004"}, dir,
                  0, err) == 0);
  REQUIRE(fs::exists(dir / "run" / "checkpoint_000000050.h5"));
  return dir;
}

std::string last_line(const std::string& text) {
  std::string t = text;
  while (!t.empty() && t.back() == '\n') t.pop_back();
  const auto at = t.rfind('\n');
  return at == std::string::npos ? t : t.substr(at + 1);
}

/// Every HDF5 dataset fields.xmf names opens, with the dimensions it states, and reads; returns
/// the number of frames the index lists.
std::size_t check_index_readable(const fs::path& dir) {
  CHECK(fsi_test::check_indexed_datasets(dir) > 0);
  return fsi_test::frames_in(dir / "fields.xmf");
}

std::vector<std::string> temporary_files(const fs::path& dir) {
  std::vector<std::string> found;
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.path().extension() == ".tmp") found.push_back(entry.path().filename().string());
  return found;
}

/// run.json is absent or whole: one JSON object with the status "failed".
void check_run_json(const fs::path& dir) {
  if (!fs::exists(dir / "run.json")) return;
  const std::string text = slurp(dir / "run.json");
  REQUIRE(text.size() > 2);
  CHECK(text.front() == '{');
  CHECK(text.substr(text.size() - 2) == "}\n");
  CHECK_THAT(text, Contains("\"status\": \"failed\""));
}

/// Overwrites entry `i` of the float64 dataset `name` of an HDF5 file (its checksum stays).
void poke(const fs::path& h5, const std::string& name, hsize_t i, double value) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const hid_t file = H5Fopen(h5.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  REQUIRE(file >= 0);
  const hid_t set = H5Dopen2(file, name.c_str(), H5P_DEFAULT);
  REQUIRE(set >= 0);
  const hid_t space = H5Dget_space(set);
  const hsize_t one = 1;
  REQUIRE(H5Sselect_hyperslab(space, H5S_SELECT_SET, &i, nullptr, &one, nullptr) >= 0);
  const hid_t mem = H5Screate_simple(1, &one, nullptr);
  REQUIRE(H5Dwrite(set, H5T_NATIVE_DOUBLE, mem, space, H5P_DEFAULT, &value) >= 0);
  H5Sclose(mem);
  H5Sclose(space);
  H5Dclose(set);
  REQUIRE(H5Fclose(file) >= 0);
}

} // namespace

TEST_CASE("apps: output: a full disk on the checkpoint path stops the run cleanly, exit 3",
          "[apps][output][disk]") {
  // The checkpoint at step 10 (97 kB), before the first frame after the initial one, is the
  // first file to pass 90 KiB.
  const fs::path dir = fresh("full_checkpoint"), out = dir / "run";
  std::string err;
  const int status =
      run_fsi({"run", fluid, "--out", out.string(), "--set", "checkpoint.interval_steps=10"}, dir,
              90 << 10, err);
  INFO(err);
  CHECK(status == 3);
  CHECK_THAT(last_line(err), Contains("run stopped: checkpoint: ") &&
                                 Contains("checkpoint_000000010.h5: cannot write: File too large"));
  CHECK(temporary_files(out).empty());
  CHECK(!fs::exists(out / "checkpoint_000000010.h5"));
  check_run_json(out);
  CHECK(fs::exists(out / "run.json")); // small: it fits
  CHECK(check_index_readable(out) >= 1);
}

TEST_CASE("apps: output: a full disk on the fields path stops between frames, exit 3",
          "[apps][output][disk]") {
  // fields.h5 (56 kB after the initial frame, then about 19 kB a frame) reaches 200 KiB first
  // (checkpoints: 97 kB).
  const fs::path dir = fresh("full_fields"), out = dir / "run";
  std::string err;
  const int status = run_fsi({"run", fluid, "--out", out.string()}, dir, 200 << 10, err);
  INFO(err);
  CHECK(status == 3);
  CHECK_THAT(last_line(err), Contains("run stopped: output: ") && Contains("fields.h5: no room") &&
                                 Contains("disk full"));
  CHECK(temporary_files(out).empty());
  check_run_json(out);
  const std::size_t frames = check_index_readable(out);
  CHECK(frames >= 3);
  CHECK(frames < 11); // stopped before the end
}

TEST_CASE("apps: output: a write that fails inside HDF5 leaves the earlier frames and no crash",
          "[apps][output][disk]") {
  // In a child process (the file size limit and HDF5's exit handler are per process): frame 0
  // is small, frame 1 far larger than the limit, so it passes the room check and fails in H5Dwrite.
  const fs::path dir = fresh("hdf5_failure");
  const pid_t pid = fork();
  REQUIRE(pid >= 0);
  if (pid == 0) {
    limit_file_size(200 << 10);
    int code = 10;
    try {
      fsi::app::FieldsFile file(dir / "fields.h5", dir / "fields.xmf");
      for (std::size_t n : {100, 100000}) {
        std::vector<double> xy(2 * n, 0.5), p(n, 2.0);
        file.begin_frame(static_cast<double>(n));
        file.write_grid("particles", xy, {{"pressure", 1, p.data()}});
        file.end_frame();
      }
      code = 11; // the second frame was written: the limit did not bite
    } catch (const fsi::RunError& e) {
      const std::string m = e.what();
      code = m.find("fields.h5") != std::string::npos ? 0 : 12;
    }
    std::exit(code); // runs HDF5's exit handler
  }
  CHECK(wait_status(pid) == 0); // not 128 + SIGSEGV
  CHECK(check_index_readable(dir) == 1);
  CHECK(temporary_files(dir).empty());
  const auto p = fsi::app::read_dataset(dir / "fields.h5", "frames/0/particles/pressure");
  CHECK(p.values == std::vector<double>(100, 2.0));
}

TEST_CASE("apps: output: a checkpoint with a changed value or a NaN is refused naming the dataset",
          "[apps][output][checkpoint]") {
  const fs::path dir = fresh("checksum");
  fsi::StateArchive a;
  a.put("fluid/x", std::vector<double>{0.0, 0.25, 0.5, 0.75});
  a.put("fluid/id", std::vector<std::int64_t>{3, 1, 2, 0});
  a.put_integer("driver/failed", 0);
  fsi::app::write_checkpoint(dir / "good.h5", a);
  CHECK(fsi::app::read_checkpoint(dir / "good.h5").reals("fluid/x")[3] == 0.75);

  fs::copy_file(dir / "good.h5", dir / "changed.h5");
  poke(dir / "changed.h5", "fluid/x", 2, 0.5000000000000001); // one bit
  CHECK_THROWS_WITH(fsi::app::read_checkpoint(dir / "changed.h5"),
                    Contains((dir / "changed.h5").string() + ": dataset 'fluid/x' is damaged"));

  a.put("fluid/x", std::vector<double>{0.0, std::nan(""), 0.5, 0.75});
  fsi::app::write_checkpoint(dir / "nan.h5", a);
  CHECK_THROWS_WITH(fsi::app::read_checkpoint(dir / "nan.h5"),
                    (dir / "nan.h5").string() +
                        ": dataset 'fluid/x' holds NaN at entry 1 (restart from another "
                        "checkpoint)");
  // The wall-hit cache may hold NaN (particles without a hit), and so may the state of a failed
  // step, kept for inspection (the driver refuses it itself).
  fsi::StateArchive hits;
  hits.put("fluid/hits/v_wall", std::vector<double>{std::nan(""), 1.0});
  fsi::app::write_checkpoint(dir / "hits.h5", hits);
  CHECK(std::isnan(fsi::app::read_checkpoint(dir / "hits.h5").reals("fluid/hits/v_wall")[0]));
  a.put_integer("driver/failed", 1);
  fsi::app::write_checkpoint(dir / "failed.h5", a);
  CHECK(std::isnan(fsi::app::read_checkpoint(dir / "failed.h5").reals("fluid/x")[1]));
  CHECK(fsi::app::checkpoint_checksum(std::vector<double>{}) == 14695981039346656037ULL);
}

TEST_CASE("apps: output: a restart from a damaged checkpoint stops with exit 2 before computing",
          "[apps][output][checkpoint]") {
  const fs::path dir = checkpointed_run("damaged_restart"), out = dir / "run";
  const fs::path checkpoint = out / "checkpoint_000000050.h5";
  std::string err;
  poke(checkpoint, "fluid/vx", 7, 123.0);
  const std::string probes = slurp(out / "probes.csv"), xmf = slurp(out / "fields.xmf");
  const int status = run_fsi({"run", fluid, "--out", out.string(), "--set", "time.end=0.004",
                              "--restart", checkpoint.string()},
                             dir, 0, err);
  CHECK(status == 2);
  CHECK_THAT(err, Contains(checkpoint.string() + ": dataset 'fluid/vx' is damaged"));
  CHECK(std::count(err.begin(), err.end(), '\n') == 1);
  CHECK(slurp(out / "probes.csv") == probes); // nothing cut back or computed
  CHECK(slurp(out / "fields.xmf") == xmf);
}

TEST_CASE("apps: output: a full disk while rewriting fields.xmf says so and keeps the pair whole",
          "[apps][output][disk]") {
  // The restart rewrites fields.xmf (to fields.xmf.tmp, renamed); fields.xmf.tmp a link to
  // /dev/full makes that write fail with ENOSPC, as on a full disk.
  const fs::path dir = checkpointed_run("full_xmf"), out = dir / "run";
  const std::string xmf = slurp(out / "fields.xmf");
  const std::size_t frames = fsi_test::frames_in(out / "fields.xmf");
  fs::create_symlink("/dev/full", out / "fields.xmf.tmp");
  std::string err;
  const int status = run_fsi({"run", fluid, "--out", out.string(), "--set", "time.end=0.008",
                              "--restart", (out / "checkpoint_000000050.h5").string()},
                             dir, 0, err);
  INFO(err);
  CHECK(status == 3);
  CHECK_THAT(last_line(err), StartsWith("run stopped: output: " + (out / "fields.xmf").string() +
                                        ": cannot write: No space left on device (disk full; "
                                        "fields.xmf is left as it was before this write)"));
  CHECK(temporary_files(out).empty());
  check_run_json(out);
  // The index as before, and every frame it names still in fields.h5 (the frames after the
  // checkpoint are deleted only once the new index is written).
  CHECK(slurp(out / "fields.xmf") == xmf);
  CHECK(frames >= 3);
  CHECK(check_index_readable(out) == frames);
}

TEST_CASE("apps: output: a restart while another process holds fields.h5 names the lock",
          "[apps][output][checkpoint]") {
  // A reader's lock, as HDF5 (h5py, ParaView) takes it on a file it has open; flock locks of two
  // open files conflict, so this process's lock is in the way of the child's HDF5.
  const fs::path dir = checkpointed_run("locked_fields"), out = dir / "run";
  const std::vector<std::string> restart = {
      "run",       fluid,
      "--out",     out.string(),
      "--set",     "time.end=0.008",
      "--restart", (out / "checkpoint_000000050.h5").string()};
  const std::string probes = slurp(out / "probes.csv");
  const int reader = ::open((out / "fields.h5").c_str(), O_RDONLY | O_CLOEXEC);
  REQUIRE(reader >= 0);
  REQUIRE(::flock(reader, LOCK_SH) == 0);
  std::string err;
  const int status = run_fsi(restart, dir, 0, err);
  ::close(reader);
  INFO(err);
  CHECK(status == 2);
  CHECK(err == (out / "fields.h5").string() +
                   ": cannot open: it is locked by another process (HDF5 file locking: a "
                   "program holds it open, e.g. a viewer, h5py or another fsi run); close it "
                   "there and try again\n");
  CHECK(slurp(out / "probes.csv") == probes); // nothing cut back
  // The lock released, the same restart runs.
  CHECK(run_fsi(restart, dir, 0, err) == 0);
}

TEST_CASE("apps: output: a checkpoint of a Courant-stepped run says so when refused",
          "[apps][output][checkpoint]") {
  const fs::path dir = checkpointed_run("courant_restart"), out = dir / "run";
  std::string err;
  // The same scene with a fixed step instead of its Courant number.
  std::string text = slurp(fluid);
  const auto at = text.find("courant: 0.2");
  REQUIRE(at != std::string::npos);
  text.replace(at, 12, "dt: 1.0e-4");
  std::ofstream(dir / "fixed.yaml") << text;
  const fs::path checkpoint = out / "checkpoint_000000050.h5";
  CHECK(run_fsi({"run", (dir / "fixed.yaml").string(), "--out", out.string(), "--set",
                 "time.end=0.004", "--restart", checkpoint.string()},
                dir, 0, err) == 2);
  CHECK(err == checkpoint.string() +
                   ": written by a Courant-stepped run (time.courant); the scene has a fixed "
                   "time.dt = 0.0001 s\n");
}
