#include "fsi_app/run.hpp"

#include "fsi/core/error.hpp"
#include "fsi/core/format.hpp"
#include "fsi/core/parallel.hpp"
#include "fsi_app/interrupt.hpp"
#include "fsi_app/output/checkpoint_file.hpp"
#include "fsi_app/output/probes_csv.hpp"
#include "fsi_app/output/text_file.hpp"
#include "fsi_app/progress.hpp"
#include "fsi_app/version.hpp"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <fcntl.h>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>
#include <sys/file.h>
#include <unistd.h>

namespace fsi::app {

namespace {

/// More steps than this are refused (fixed dt: up front; adaptive: when the step falls so low
/// that more would remain): docs/reliability.md, "Time steps".
constexpr double kMaxSteps = 1e9;

std::string iso_time(std::chrono::system_clock::time_point t) {
  const std::time_t tt = std::chrono::system_clock::to_time_t(t);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&tt));
  return buf;
}

std::string json_strings(const std::vector<std::string>& items) {
  std::string out = "[";
  for (std::size_t i = 0; i < items.size(); ++i)
    out += (i ? ", " : "") + JsonObject::quote(items[i]);
  return out + "]";
}

std::string format_g(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

/// Strings as one int64 array (bytes, each string ended by 0), for the checkpoint.
std::vector<std::int64_t> encode_strings(const std::vector<std::string>& items) {
  std::vector<std::int64_t> out;
  for (const auto& s : items) {
    for (const char ch : s) out.push_back(static_cast<unsigned char>(ch));
    out.push_back(0);
  }
  return out;
}
std::vector<std::string> decode_strings(const std::vector<std::int64_t>& bytes) {
  std::vector<std::string> out;
  std::string current;
  for (const std::int64_t b : bytes) {
    if (b == 0) {
      out.push_back(current);
      current.clear();
    } else {
      current += static_cast<char>(b);
    }
  }
  return out;
}

/// `--set A --set B` for messages ("none" when empty).
std::string describe_overrides(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& s : items) out += (out.empty() ? "--set " : " --set ") + s;
  return out.empty() ? "no --set" : out;
}

/// A restart must give the overrides of the run that wrote the checkpoint (a time.end of its own
/// is allowed: extending a run). Empty when they agree, else what differs.
std::string override_difference(std::vector<std::string> written, std::vector<std::string> given) {
  auto is_end = [](const std::string& s) { return s.rfind("time.end=", 0) == 0; };
  if (std::any_of(given.begin(), given.end(), is_end)) {
    std::erase_if(written, is_end);
    std::erase_if(given, is_end);
  }
  if (written == given) return {};
  std::vector<std::string> missing, extra;
  for (const auto& w : written)
    if (std::find(given.begin(), given.end(), w) == given.end()) missing.push_back(w);
  for (const auto& g : given)
    if (std::find(written.begin(), written.end(), g) == written.end()) extra.push_back(g);
  std::string what =
      "written with " + describe_overrides(written) + ", this run has " + describe_overrides(given);
  if (!missing.empty()) what += "; missing: " + describe_overrides(missing);
  if (!extra.empty()) what += "; not in the checkpoint: " + describe_overrides(extra);
  if (missing.empty() && extra.empty()) what += " (another order)";
  return what + "; give the checkpoint's overrides";
}

/// fields.h5 / fields.xmf, probes.csv and the models' logs; new, or continued after a restart
/// from the first `resume` frames.
class Recorder {
public:
  Recorder(const Scene& scene, const std::vector<std::unique_ptr<Model>>& models,
           const std::filesystem::path& out, std::optional<int> resume, const Ranks& ranks)
      : scene_(scene), models_(models), ranks_(ranks) {
    if (ranks.rank() != 0) return; // rank 0 writes the files
    const auto h5 = out / "fields.h5", xmf = out / "fields.xmf", csv = out / "probes.csv";
    fields_ = resume ? std::make_unique<FieldsFile>(h5, xmf, *resume)
                     : std::make_unique<FieldsFile>(h5, xmf);
    probes_ = resume ? std::make_unique<ProbesCsv>(csv, probe_names(scene),
                                                   static_cast<std::size_t>(*resume))
                     : std::make_unique<ProbesCsv>(csv, probe_names(scene));
    for (const auto& m : models_) {
      m->open_logs(out, resume.has_value());
      if (!resume) m->declare(*fields_);
    }
  }

  void frame(double time) {
    for (const auto& m : models_) m->gather_frame();
    if (ranks_.rank() != 0) {
      ++frames_;
      return;
    }
    fields_->begin_frame(time);
    for (const auto& m : models_) m->write_frame(*fields_, scene_.output.fields);
    fields_->end_frame();
    std::vector<double> values;
    for (const auto& p : scene_.output.probes) values.push_back(probe(p));
    probes_->row(time, values);
  }

  int frames() const { return fields_ ? fields_->frames() : frames_; }

private:
  static std::vector<std::string> probe_names(const Scene& scene) {
    std::vector<std::string> names;
    for (const auto& p : scene.output.probes) names.push_back(p.name);
    return names;
  }
  double probe(const ProbeSpec& p) const {
    for (const auto& m : models_)
      if (auto v = m->probe(p)) return *v;
    throw InputError(scene_.path.string() + ":" + std::to_string(p.line) + ": output.probes: '" +
                     p.name + "' is answered by no part of the scene");
  }

  const Scene& scene_;
  const std::vector<std::unique_ptr<Model>>& models_;
  const Ranks& ranks_;
  int frames_ = 0; // counted on the ranks without the files
  std::unique_ptr<FieldsFile> fields_;
  std::unique_ptr<ProbesCsv> probes_;
};

/// The driver's own state, checkpointed under "driver/" beside the models'.
struct Clock {
  long step = 0;
  double time = 0.0, next_frame = 0.0;
  int frames = 0;
  double dt_min = std::numeric_limits<double>::infinity(), dt_max = 0.0;
};

StateArchive make_archive(const Scene& scene, const std::vector<std::unique_ptr<Model>>& models,
                          const Clock& c, bool failed) {
  StateArchive a;
  a.put_integer("driver/step", c.step);
  a.put_real("driver/time", c.time);
  a.put_real("driver/next_frame", c.next_frame);
  a.put_integer("driver/frames", c.frames);
  a.put_real("driver/dt_min", c.dt_min);
  a.put_real("driver/dt_max", c.dt_max);
  a.put_real("driver/dt", scene.time.dt.value_or(0.0));
  a.put_integer("driver/threads", num_threads());
  a.put_integer("driver/failed", failed);
  a.put("driver/overrides", encode_strings(scene.overrides));
  a.put_integer("driver/scene_digest", static_cast<std::int64_t>(scene.digest));
  for (const auto& m : models) m->write_state(a);
  return a;
}

/// Why a checkpoint's step does not fit the scene's: dt = 0 is a Courant-stepped run. Six
/// digits, or 17 when six would print the two steps alike.
std::string step_mismatch(double written, double scene) {
  const auto print = significant;
  const int digits = print(written, 6) == print(scene, 6) ? 17 : 6;
  if (written == 0.0)
    return "written by a Courant-stepped run (time.courant); the scene has a fixed time.dt = " +
           print(scene, digits) + " s";
  if (scene == 0.0)
    return "written with a fixed time.dt = " + print(written, digits) +
           " s; the scene is Courant-stepped (time.courant)";
  return "written with time.dt = " + print(written, digits) +
         " s; the scene has time.dt = " + print(scene, digits) + " s";
}

/// Reads the driver's state and the models' from a restart checkpoint.
Clock read_archive(const Scene& scene, std::vector<std::unique_ptr<Model>>& models,
                   const std::filesystem::path& file, std::ostream& log) {
  const StateArchive a = read_checkpoint(file);
  Clock c;
  try {
    if (a.integer("driver/failed") != 0)
      throw InputError("the state of a failed step, kept for inspection; restart from a "
                       "checkpoint_*.h5 written before it");
    if (a.real("driver/dt") != scene.time.dt.value_or(0.0))
      throw InputError(step_mismatch(a.real("driver/dt"), scene.time.dt.value_or(0.0)));
    c.step = a.integer("driver/step");
    c.time = a.real("driver/time");
    c.next_frame = a.real("driver/next_frame");
    c.frames = static_cast<int>(a.integer("driver/frames"));
    c.dt_min = a.real("driver/dt_min");
    c.dt_max = a.real("driver/dt_max");
    for (auto& m : models) m->read_state(a);
    // After the state (a checkpoint of another mesh names its key first); checkpoints written
    // before the overrides were recorded have no entry.
    if (a.all_integers().count("driver/overrides")) {
      const std::string diff =
          override_difference(decode_strings(a.integers("driver/overrides")), scene.overrides);
      if (!diff.empty()) throw InputError(diff);
    }
    // A scene edited since the checkpoint (checkpoints before the digest have none).
    if (a.all_integers().count("driver/scene_digest") &&
        static_cast<std::uint64_t>(a.integer("driver/scene_digest")) != scene.digest)
      throw InputError("written for another version of " + scene.path.string() +
                       ": the scene was edited since (a restart may change time.end only, in the "
                       "file or by --set); restore the scene, or start a new run");
    if (c.time > scene.time.end * (1.0 + 1e-12))
      throw InputError("at t = " + format_g(c.time) +
                       " s, past time.end = " + format_g(scene.time.end) + " s of this run");
  } catch (const InputError& e) {
    throw InputError(file.string() + ": " + e.what());
  }
  if (a.integer("driver/threads") != num_threads())
    log << "note: " << file.string() << " was written with " << a.integer("driver/threads")
        << " threads, this run has " << num_threads()
        << " (results do not depend on the thread count: docs/reliability.md, Determinism)\n";
  return c;
}

std::filesystem::path checkpoint_path(const std::filesystem::path& out, long step) {
  char name[48];
  std::snprintf(name, sizeof name, "checkpoint_%09ld.h5", step);
  return out / name;
}

/// Deletes all but the newest `keep` checkpoint_*.h5 up to `step` (later ones belong to a run
/// that a restart abandoned; they are overwritten as this one gets there).
void prune_checkpoints(const std::filesystem::path& out, long step, int keep) {
  std::vector<std::pair<long, std::filesystem::path>> found;
  for (const auto& entry : std::filesystem::directory_iterator(out)) {
    const std::string name = entry.path().filename().string();
    long s = 0;
    char tail[8] = {};
    if (std::sscanf(name.c_str(), "checkpoint_%ld%7s", &s, tail) == 2 &&
        std::string(tail) == ".h5" && s <= step)
      found.emplace_back(s, entry.path());
  }
  std::sort(found.begin(), found.end());
  for (std::size_t i = 0; i + static_cast<std::size_t>(keep) < found.size(); ++i)
    std::filesystem::remove(found[i].second);
}

/// The files a run writes in its output folder (and their temporary names).
bool is_run_file(const std::string& name) {
  static const std::vector<std::string> files = {"fields.h5",      "fields.xmf",   "probes.csv",
                                                 "run.json",       "coupling.csv", "interface.h5",
                                                 "failed_state.h5"};
  std::string base = name;
  if (base.ends_with(".tmp")) base.resize(base.size() - 4);
  if (std::find(files.begin(), files.end(), base) != files.end()) return true;
  long step = 0;
  char tail[8] = {};
  return std::sscanf(base.c_str(), "checkpoint_%ld%7s", &step, tail) == 2 &&
         std::string(tail) == ".h5";
}

/// One run per output folder: flock on DIR/.lock, held until the process ends or the run
/// returns. Taken before anything else is written; a folder of another run is refused unless
/// `overwrite` (then exactly the run files are deleted).
class OutputLock {
public:
  OutputLock(const std::filesystem::path& out, bool fresh, bool overwrite) {
    namespace fs = std::filesystem;
    const std::string dir = out.string();
    std::error_code ec;
    if (fs::exists(out, ec) && !fs::is_directory(out, ec))
      throw InputError(dir + ": --out: exists and is not a folder; give a folder");
    fs::create_directories(out, ec);
    if (ec) throw InputError(dir + ": --out: cannot create the folder (" + ec.message() + ")");
    const fs::path lock = out / ".lock";
    fd_ = open(lock.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0)
      throw InputError(dir + ": --out: cannot write in this folder (" + std::strerror(errno) + ")");
    if (flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      close(fd_);
      throw InputError(dir + ": --out: another fsi run is writing to this folder (it holds " +
                       lock.string() + "); give another --out");
    }
    if (!fresh) return;
    std::vector<fs::path> found;
    for (const auto& entry : fs::directory_iterator(out, ec))
      if (is_run_file(entry.path().filename().string())) found.push_back(entry.path());
    std::sort(found.begin(), found.end());
    if (!found.empty() && !overwrite) {
      close(fd_);
      std::string names;
      for (std::size_t i = 0; i < found.size() && i < 4; ++i)
        names += (i ? ", " : "") + found[i].filename().string();
      if (found.size() > 4) names += ", ...";
      throw InputError(dir + ": --out holds the files of an earlier run (" + names +
                       "); give another folder, --restart from one of its checkpoints, or "
                       "--overwrite to delete them");
    }
    for (const auto& f : found) {
      fs::remove(f, ec);
      if (ec) {
        close(fd_);
        throw InputError(f.string() + ": --overwrite: cannot delete (" + ec.message() + ")");
      }
    }
  }
  ~OutputLock() { close(fd_); }
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;

private:
  int fd_ = -1;
};

} // namespace

double max_steps() {
  return kMaxSteps;
}

RunResult run_scene(const Scene& scene, std::vector<std::unique_ptr<Model>>& models,
                    const RunOptions& options) {
  const double end = scene.time.end, interval = scene.output.interval;
  // Fixed step: the number of steps, the last one shortened to end exactly at time.end.
  const double fixed_steps = scene.time.dt ? end / *scene.time.dt : 0.0;
  if (!(fixed_steps <= kMaxSteps))
    throw InputError(scene.path.string() + ": time: time.end / time.dt = " + format_g(fixed_steps) +
                     " steps; a run takes at most " + format_g(kMaxSteps));
  const OneProcess one;
  const Ranks& ranks = options.ranks ? *options.ranks : one;
  const bool root = ranks.rank() == 0;
  // Rank 0 holds the folder; every rank learns whether it could (InputError on each, printed by
  // rank 0).
  std::optional<OutputLock> lock;
  std::string refused;
  try {
    if (root) lock.emplace(options.out, options.restart.empty(), options.overwrite);
  } catch (const InputError& e) {
    refused = e.what();
  }
  if (!ranks.all(refused.empty())) throw InputError(refused);
  std::ostream& log = *options.log;
  Clock c;
  c.next_frame = std::min(interval, end);
  std::optional<int> resume;
  long checkpoint_step = -1; // step of the last checkpoint on disk
  if (!options.restart.empty()) {
    c = read_archive(scene, models, options.restart, log);
    resume = c.frames;
    checkpoint_step = c.step;
  }
  const auto start = std::chrono::system_clock::now();
  const auto wall_start = std::chrono::steady_clock::now();
  std::string status = "completed", message;
  RunResult result;
  // The step: fixed (time = step * dt exactly, frames every round(interval / dt) steps, the last
  // step shortened to end at time.end), or the smallest stable step of the models for the
  // Courant number, shortened to land on frames (the last two steps before a frame share what is
  // left when it is under two steps, so no sliver of a step). An adaptive step so small that more
  // than kMaxSteps steps would remain stops the run.
  const long fixed_total =
      scene.time.dt ? std::max(1L, static_cast<long>(std::ceil(fixed_steps - 1e-9))) : 0;
  const long fixed_per_frame =
      scene.time.dt ? std::max(1L, static_cast<long>(std::min(std::round(interval / *scene.time.dt),
                                                              static_cast<double>(fixed_total))))
                    : 0;
  auto next_dt = [&] {
    if (scene.time.dt) {
      const double dt = *scene.time.dt;
      const double last = end - static_cast<double>(fixed_total - 1) * dt;
      return c.step + 1 == fixed_total && std::abs(last - dt) > 1e-9 * dt ? last : dt;
    }
    double dt = std::numeric_limits<double>::infinity();
    for (const auto& m : models)
      if (auto s = m->stable_dt(*scene.time.courant)) dt = std::min(dt, *s);
    if (!(dt > 0.0) || !((end - c.time) / dt <= kMaxSteps))
      throw RunError(
          "time step: the stable step is " + format_g(dt) + " s at step " + std::to_string(c.step) +
          ", t = " + format_g(c.time) + " s: reaching time.end = " + format_g(end) +
          " s would take " + format_g((end - c.time) / dt) + " more steps, above the limit of " +
          format_g(kMaxSteps) + " (check time.courant, fluid.viscosity, fluid.sound_speed)");
    // Land on the next frame without a sliver of a step: what is left of the frame in one step
    // if it fits, in two equal ones if it is under two steps.
    const double left = c.next_frame - c.time;
    return left <= dt ? left : left < 2.0 * dt ? 0.5 * left : dt;
  };
  auto last_checkpoint = std::chrono::steady_clock::now();
  auto run_json = [&](const std::string& run_status, const std::string& run_message,
                      bool with_models) {
    JsonObject run;
    run.add("scene", scene.path.string())
        .add("name", scene.name)
        .add_raw("overrides", json_strings(scene.overrides))
        .add("version", version())
        .add("git_revision", git_revision())
        .add("start", iso_time(start))
        .add("end", iso_time(std::chrono::system_clock::now()))
        .add("wall_seconds",
             std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count())
        .add("threads", num_threads());
    if (ranks.decomposed()) run.add("processes", ranks.size());
    run.add("status", run_status)
        .add("message", run_message)
        .add("restarted_from", options.restart.string())
        .add("checkpoint", result.checkpoint.string())
        .add("steps", static_cast<long long>(c.step))
        .add("simulated_time", c.time)
        .add("dt_min", c.dt_min)
        .add("dt_max", c.dt_max)
        .add("frames", c.frames);
    if (with_models)
      for (const auto& m : models) m->report(run);
    return run.str() + '\n';
  };
  InterruptGuard interrupt;
  // What a second signal leaves as run.json (it ends the process at once).
  auto update_last_words = [&] {
    if (!root) return;
    interrupt.set_last_words(
        options.out / "run.json",
        run_json("interrupted",
                 "stopped at once by a second signal after step " + std::to_string(c.step) +
                     " (t = " + format_g(c.time) + " s); " +
                     (result.checkpoint.empty()
                          ? std::string("no checkpoint was written")
                          : "continue from the last checkpoint, " + result.checkpoint.string()),
                 false));
  };
  auto checkpoint = [&] {
    for (const auto& m : models) m->flush_logs();
    result.checkpoint = checkpoint_path(options.out, c.step);
    write_checkpoint(result.checkpoint, make_archive(scene, models, c, false));
    prune_checkpoints(options.out, c.step, scene.checkpoint ? scene.checkpoint->keep : 2);
    last_checkpoint = std::chrono::steady_clock::now();
    checkpoint_step = c.step;
    update_last_words();
  };
  auto checkpoint_due = [&] {
    if (!scene.checkpoint) return false;
    const auto& k = *scene.checkpoint;
    const double minutes =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - last_checkpoint).count() /
        60.0;
    return (k.interval_steps && c.step % *k.interval_steps == 0) ||
           (k.interval_minutes && minutes >= *k.interval_minutes);
  };
  std::optional<Recorder> recorder;
  double attempted = c.time; // end of the step in progress, for a failure's last frame
  bool state_broken = true;  // false when the run stopped before a step (the step limit)
  update_last_words();
  try {
    recorder.emplace(scene, models, options.out, resume, ranks);
    if (!resume) {
      recorder->frame(0.0);
      c.frames = recorder->frames();
    }
    Progress progress(end, options.terminal, log, c.step, c.time);
    while (scene.time.dt ? c.step < fixed_total : c.time < end * (1.0 - 1e-12)) {
      double dt = 0.0;
      try {
        dt = next_dt();
      } catch (const RunError&) {
        state_broken = false;
        throw;
      }
      attempted = c.time + dt;
      std::vector<std::optional<ParticleCount>> particles;
      for (const auto& m : models) particles.push_back(m->particle_count());
      for (auto& m : models) m->advance(c.time, dt);
      for (std::size_t k = 0; k < models.size(); ++k)
        if (auto what = models[k]->non_finite())
          throw RunError(*what + " after step " + std::to_string(c.step + 1) +
                         ", t = " + format_g(attempted) + " s");
      for (std::size_t k = 0; k < models.size(); ++k)
        if (particles[k])
          check_particle_loss(*particles[k], *models[k]->particle_count(), c.step + 1, c.time,
                              attempted);
      ++c.step;
      c.time = scene.time.dt ? static_cast<double>(c.step) * *scene.time.dt : c.time + dt;
      // The last step ends at time.end exactly.
      if (scene.time.dt ? c.step == fixed_total : c.time >= end * (1.0 - 1e-12)) c.time = end;
      c.dt_min = std::min(c.dt_min, dt), c.dt_max = std::max(c.dt_max, dt);
      const bool frame = scene.time.dt ? c.step % fixed_per_frame == 0 || c.step == fixed_total
                                       : c.time >= c.next_frame * (1.0 - 1e-12);
      if (frame) {
        recorder->frame(c.time);
        c.frames = recorder->frames();
        c.next_frame = std::min(c.next_frame + interval, end);
        update_last_words();
      }
      for (auto& m : models)
        for (const auto& note : m->take_notes()) log << "note: " << note << '\n';
      progress.update(c.time, c.step);
      if (options.on_step) options.on_step(c.time, c.step);
      if (checkpoint_due()) checkpoint();
      // Decomposed: the ranks stop at the same step (the largest signal any rank received).
      result.signal = ranks.decomposed()
                          ? static_cast<int>(ranks.max(static_cast<double>(interrupt.received())))
                          : interrupt.received();
      if (result.signal != 0) {
        if (checkpoint_step != c.step && !ranks.decomposed()) checkpoint();
        status = "interrupted";
        message = "stopped by signal " + std::to_string(result.signal) + " after step " +
                  std::to_string(c.step);
        break;
      }
    }
    if (!result.signal) {
      progress.finish(c.time, c.step);
      if (scene.checkpoint && checkpoint_step != c.step) checkpoint();
    }
  } catch (const RunError& e) {
    status = "failed";
    message = e.what();
    // The last state: a frame at the failed step's end time and failed_state.h5 (inspection).
    if (state_broken) {
      std::string kept;
      try {
        if (recorder) {
          recorder->frame(attempted);
          c.frames = recorder->frames();
          kept = "frame " + std::to_string(c.frames - 1) + " of " +
                 (options.out / "fields.xmf").string() + ", ";
        }
        for (const auto& m : models) m->flush_logs();
        Clock failed = c;
        failed.time = attempted;
        if (ranks.decomposed()) { // no checkpoints of a decomposed fluid yet (issue 47)
          kept += "no failed_state.h5 under mpirun";
        } else {
          write_checkpoint(options.out / "failed_state.h5",
                           make_archive(scene, models, failed, true));
          kept += (options.out / "failed_state.h5").string();
        }
      } catch (const std::exception& f) {
        kept += std::string("not all written: ") + f.what();
      }
      message += " (last state: " + kept + ")";
    } else {
      for (const auto& m : models) m->flush_logs();
    }
  }
  // run.json whole or absent (a full disk): written to run.json.tmp, then renamed.
  try {
    const std::string json = run_json(status, message, true); // collective when decomposed
    if (root) write_file_atomically(options.out / "run.json", json);
  } catch (const RunError& e) {
    std::error_code ignored;
    std::filesystem::remove(options.out / "run.json", ignored); // not an earlier state's
    message = status == "failed" ? message + "; " + e.what() : std::string(e.what());
    status = "failed";
  }
  if (status == "failed") throw RunError(message);
  result.step = c.step;
  result.time = c.time;
  return result;
}

} // namespace fsi::app
