#include "fsi_app/run.hpp"

#include "fsi/core/error.hpp"
#include "fsi/core/parallel.hpp"
#include "fsi_app/interrupt.hpp"
#include "fsi_app/output/checkpoint_file.hpp"
#include "fsi_app/output/probes_csv.hpp"
#include "fsi_app/output/text_file.hpp"
#include "fsi_app/progress.hpp"
#include "fsi_app/version.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>

namespace fsi::app {

namespace {

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

/// fields.h5 / fields.xmf, probes.csv and the models' logs; new, or continued after a restart
/// from the first `resume` frames.
class Recorder {
public:
  Recorder(const Scene& scene, const std::vector<std::unique_ptr<Model>>& models,
           const std::filesystem::path& out, std::optional<int> resume)
      : scene_(scene), models_(models) {
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
    fields_->begin_frame(time);
    for (const auto& m : models_) m->write_frame(*fields_, scene_.output.fields);
    fields_->end_frame();
    std::vector<double> values;
    for (const auto& p : scene_.output.probes) values.push_back(probe(p));
    probes_->row(time, values);
  }

  int frames() const { return fields_->frames(); }

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
  for (const auto& m : models) m->write_state(a);
  return a;
}

/// Why a checkpoint's step does not fit the scene's: dt = 0 is a Courant-stepped run. Six
/// digits, or 17 when six would print the two steps alike.
std::string step_mismatch(double written, double scene) {
  auto print = [](double v, int digits) {
    std::ostringstream o;
    o << std::setprecision(digits) << v;
    return o.str();
  };
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
  } catch (const InputError& e) {
    throw InputError(file.string() + ": " + e.what());
  }
  if (a.integer("driver/threads") != num_threads())
    log << "note: " << file.string() << " was written with " << a.integer("driver/threads")
        << " threads, this run has " << num_threads()
        << " (results then differ within the tolerance of docs/reliability.md)\n";
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

} // namespace

RunResult run_scene(const Scene& scene, std::vector<std::unique_ptr<Model>>& models,
                    const RunOptions& options) {
  std::filesystem::create_directories(options.out);
  std::ostream& log = *options.log;
  const double end = scene.time.end, interval = scene.output.interval;
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
  // The step: fixed (time = step * dt exactly, frames every round(interval / dt) steps), or the
  // smallest stable step of the models for the Courant number, shortened to land on frames.
  auto next_dt = [&] {
    if (scene.time.dt) return *scene.time.dt;
    double dt = std::numeric_limits<double>::infinity();
    for (const auto& m : models)
      if (auto s = m->stable_dt(*scene.time.courant)) dt = std::min(dt, *s);
    return std::min(dt, c.next_frame - c.time);
  };
  auto last_checkpoint = std::chrono::steady_clock::now();
  auto checkpoint = [&] {
    for (const auto& m : models) m->flush_logs();
    result.checkpoint = checkpoint_path(options.out, c.step);
    write_checkpoint(result.checkpoint, make_archive(scene, models, c, false));
    prune_checkpoints(options.out, c.step, scene.checkpoint ? scene.checkpoint->keep : 2);
    last_checkpoint = std::chrono::steady_clock::now();
    checkpoint_step = c.step;
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
  InterruptGuard interrupt;
  double attempted = c.time; // end of the step in progress, for a failure's last frame
  try {
    recorder.emplace(scene, models, options.out, resume);
    if (!resume) {
      recorder->frame(0.0);
      c.frames = recorder->frames();
    }
    Progress progress(end, options.terminal, log, c.step, c.time);
    const long fixed_total =
        scene.time.dt ? std::lround(std::ceil(end / *scene.time.dt - 1e-9)) : 0;
    const long fixed_per_frame =
        scene.time.dt ? std::max(1L, std::lround(interval / *scene.time.dt)) : 0;
    while (scene.time.dt ? c.step < fixed_total : c.time < end * (1.0 - 1e-12)) {
      const double dt = next_dt();
      attempted = c.time + dt;
      for (auto& m : models) m->advance(c.time, dt);
      ++c.step;
      c.time = scene.time.dt ? static_cast<double>(c.step) * dt : c.time + dt;
      c.dt_min = std::min(c.dt_min, dt), c.dt_max = std::max(c.dt_max, dt);
      const bool frame = scene.time.dt ? c.step % fixed_per_frame == 0 || c.step == fixed_total
                                       : c.time >= c.next_frame * (1.0 - 1e-12);
      if (frame) {
        recorder->frame(c.time);
        c.frames = recorder->frames();
        c.next_frame = std::min(c.next_frame + interval, end);
      }
      progress.update(c.time, c.step);
      if (checkpoint_due()) checkpoint();
      if ((result.signal = interrupt.received()) != 0) {
        if (checkpoint_step != c.step) checkpoint();
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
      write_checkpoint(options.out / "failed_state.h5", make_archive(scene, models, failed, true));
      kept += (options.out / "failed_state.h5").string();
    } catch (const std::exception& f) {
      kept += std::string("not all written: ") + f.what();
    }
    message += " (last state: " + kept + ")";
  }

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
      .add("threads", num_threads())
      .add("status", status)
      .add("message", message)
      .add("restarted_from", options.restart.string())
      .add("checkpoint", result.checkpoint.string())
      .add("steps", static_cast<long long>(c.step))
      .add("simulated_time", c.time)
      .add("dt_min", c.dt_min)
      .add("dt_max", c.dt_max)
      .add("frames", c.frames);
  for (const auto& m : models) m->report(run);
  // run.json whole or absent (a full disk): written to run.json.tmp, then renamed.
  try {
    write_file_atomically(options.out / "run.json", run.str() + '\n');
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
