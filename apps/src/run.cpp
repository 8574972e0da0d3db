#include "fsi_app/run.hpp"

#include "fsi/core/error.hpp"
#include "fsi/core/format.hpp"
#include "fsi/core/parallel.hpp"
#include "fsi_app/interrupt.hpp"
#include "fsi_app/output/checkpoint_file.hpp"
#include "fsi_app/output/output_folder.hpp"
#include "fsi_app/output/probes_csv.hpp"
#include "fsi_app/output/text_file.hpp"
#include "fsi_app/progress.hpp"
#include "fsi_app/run_state.hpp"
#include "fsi_app/thread_governor.hpp"
#include "fsi_app/version.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <limits>

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

/// fields.h5 / fields.xmf, probes.csv and the models' logs; new, or continued after a restart
/// from the first `resume` frames.
class Recorder {
public:
  /// `seconds`: the wall time of the frames (models' gathers, fields.h5, probes) is added to it.
  Recorder(const Scene& scene, const std::vector<std::unique_ptr<Model>>& models,
           const std::filesystem::path& out, std::optional<int> resume, const Ranks& ranks,
           double& seconds)
      : scene_(scene), models_(models), ranks_(ranks), seconds_(seconds) {
    // Rank 0 writes the files; fields.h5 with every rank when written collectively.
    const auto h5 = out / "fields.h5", xmf = out / "fields.xmf", csv = out / "probes.csv";
    const Ranks* collective = writes_collectively(ranks) ? &ranks : nullptr;
    if (ranks.rank() == 0 || collective)
      fields_ = resume ? std::make_unique<FieldsFile>(h5, xmf, *resume, collective)
                       : std::make_unique<FieldsFile>(h5, xmf, collective);
    if (ranks.rank() != 0) {
      if (fields_ && !resume)
        for (const auto& m : models_) m->declare(*fields_);
      frames_ = resume.value_or(0);
      return;
    }
    probes_ = resume ? std::make_unique<ProbesCsv>(csv, probe_names(scene),
                                                   static_cast<std::size_t>(*resume))
                     : std::make_unique<ProbesCsv>(csv, probe_names(scene));
    for (const auto& m : models_) {
      m->open_logs(out, resume.has_value());
      if (!resume) m->declare(*fields_);
    }
  }

  void frame(double time) {
    const auto start = std::chrono::steady_clock::now();
    frame_at(time);
    seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  int frames() const { return fields_ ? fields_->frames() : frames_; }

private:
  void frame_at(double time) {
    for (const auto& m : models_) m->gather_frame();
    if (fields_) {
      fields_->begin_frame(time);
      for (const auto& m : models_) m->write_frame(*fields_, scene_.output.fields);
      fields_->end_frame();
    }
    if (ranks_.rank() != 0) {
      ++frames_;
      return;
    }
    std::vector<double> values;
    for (const auto& p : scene_.output.probes) values.push_back(probe(p));
    probes_->row(time, values);
  }

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
  double& seconds_;
  int frames_ = 0; // counted on the ranks other than 0 (which may hold fields_ too)
  std::unique_ptr<FieldsFile> fields_;
  std::unique_ptr<ProbesCsv> probes_;
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
    throw InputError(scene.path.string() +
                     ": time: time.end / time.dt = " + significant(fixed_steps, 6) +
                     " steps; a run takes at most " + significant(kMaxSteps, 6));
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
  RunClock c;
  c.next_frame = std::min(interval, end);
  std::optional<int> resume;
  long checkpoint_step = -1; // step of the last checkpoint on disk
  if (!options.restart.empty()) {
    c = read_archive(scene, models, options.restart, log);
    resume = c.frames;
    checkpoint_step = c.step;
  }
  // Decomposed: every rank built the scene with its block of each particle fluid (or read the
  // whole checkpoint); the models partition it now (a restart: afresh, on any rank count).
  if (ranks.decomposed())
    for (auto& m : models) try {
        if (!m->decompose(ranks)) throw InputError("a part of it cannot run under mpirun");
      } catch (const InputError& e) {
        const std::string what = e.what();
        if (what.rfind(scene.path.string() + ":", 0) == 0) throw; // FILE:LINE: key: what
        const auto& named = options.restart.empty() ? scene.path : options.restart;
        throw InputError(named.string() + ": " + what);
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
      throw RunError("time step: the stable step is " + significant(dt, 6) + " s at step " +
                     std::to_string(c.step) + ", t = " + significant(c.time, 6) +
                     " s: reaching time.end = " + significant(end, 6) + " s would take " +
                     significant((end - c.time) / dt, 6) + " more steps, above the limit of " +
                     significant(kMaxSteps, 6) +
                     " (check time.courant, fluid.viscosity, fluid.sound_speed)");
    // Land on the next frame without a sliver of a step: what is left of the frame in one step
    // if it fits, in two equal ones if it is under two steps.
    const double left = c.next_frame - c.time;
    return left <= dt ? left : left < 2.0 * dt ? 0.5 * left : dt;
  };
  auto last_checkpoint = std::chrono::steady_clock::now();
  double frame_seconds = 0.0; // this rank's wall time writing frames (Recorder)
  // Each step's thread count, from the steps' wall times; the asked count again after the run.
  ThreadGovernor governor(num_threads());
  struct RestoreThreads {
    int threads;
    ~RestoreThreads() { set_num_threads(threads); }
  } restore_threads{governor.most()};
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
        .add("threads", governor.most())
        .add("thread_governor", governor.report());
    if (ranks.decomposed()) run.add("processes", ranks.size());
    run.add("status", run_status)
        .add("message", run_message)
        .add("restarted_from", options.restart.string())
        .add("checkpoint", result.checkpoint.string())
        .add("steps", static_cast<long long>(c.step))
        .add("simulated_time", c.time)
        .add("dt_min", c.dt_min)
        .add("dt_max", c.dt_max)
        .add("frames", c.frames)
        .add("frame_seconds", frame_seconds);
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
                     " (t = " + significant(c.time, 6) + " s); " +
                     (result.checkpoint.empty()
                          ? std::string("no checkpoint was written")
                          : "continue from the last checkpoint, " + result.checkpoint.string()),
                 false));
  };
  std::optional<Recorder> recorder;
  double attempted = c.time; // end of the step in progress, for a failure's last frame
  bool state_broken = true;  // false when the run stopped before a step (the step limit)
  // Decomposed: the archive is gathered (collective) and rank 0 writes the one file.
  auto checkpoint = [&] {
    for (const auto& m : models) m->flush_logs();
    result.checkpoint = checkpoint_path(options.out, c.step);
    const StateArchive archive = make_archive(scene, models, c, false, governor.most());
    last_checkpoint = std::chrono::steady_clock::now();
    checkpoint_step = c.step;
    if (!root) return;
    write_checkpoint(result.checkpoint, archive);
    prune_checkpoints(options.out, c.step, scene.checkpoint ? scene.checkpoint->keep : 2);
    update_last_words();
  };
  // After the step loop (a signal, the end): a rank 0 that fails to write stops every rank.
  auto last_checkpoint_agreed = [&] {
    std::string failure;
    try {
      checkpoint();
    } catch (const std::exception& e) {
      if (!ranks.decomposed()) throw;
      failure = e.what();
    }
    const Ranks::Agreed agreed = ranks.agree(0, failure);
    if (!agreed.failure.empty()) {
      state_broken = false; // the state is sound; its checkpoint is what failed
      throw RunError(agreed.failure);
    }
  };
  auto checkpoint_due = [&] {
    if (!scene.checkpoint) return false;
    const auto& k = *scene.checkpoint;
    const double minutes =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - last_checkpoint).count() /
        60.0;
    // Wall time differs between ranks: due when due on any.
    const bool late = k.interval_minutes && minutes >= *k.interval_minutes;
    return (k.interval_steps && c.step % *k.interval_steps == 0) ||
           (k.interval_minutes && !ranks.all(!late));
  };
  update_last_words();
  try {
    recorder.emplace(scene, models, options.out, resume, ranks, frame_seconds);
    if (!resume) {
      recorder->frame(0.0);
      c.frames = recorder->frames();
    }
    Progress progress(end, options.terminal, log, c.step, c.time);
    while (scene.time.dt ? c.step < fixed_total : c.time < end * (1.0 - 1e-12)) {
      set_num_threads(governor.threads());
      const double step_start = wall_time();
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
                         ", t = " + significant(attempted, 6) + " s");
      for (std::size_t k = 0; k < models.size(); ++k)
        if (particles[k])
          check_particle_loss(*particles[k], *models[k]->particle_count(), c.step + 1, c.time,
                              attempted);
      governor.record(wall_time() - step_start);
      ++c.step;
      c.time = scene.time.dt ? static_cast<double>(c.step) * *scene.time.dt : c.time + dt;
      // The last step ends at time.end exactly.
      if (scene.time.dt ? c.step == fixed_total : c.time >= end * (1.0 - 1e-12)) c.time = end;
      c.dt_min = std::min(c.dt_min, dt), c.dt_max = std::max(c.dt_max, dt);
      const bool frame = scene.time.dt ? c.step % fixed_per_frame == 0 || c.step == fixed_total
                                       : c.time >= c.next_frame * (1.0 - 1e-12);
      // Decomposed: what fails here on one rank (rank 0 writing the files) is agreed below, so
      // no rank waits for it in the next step's collectives.
      std::string failure;
      try {
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
      } catch (const AgreedError&) { // fields.h5 failed on some rank: every rank is here
        state_broken = false;
        throw;
      } catch (const std::exception& e) {
        if (!ranks.decomposed()) throw;
        failure = e.what();
      }
      // The step's collective point: the ranks stop at the same step (the largest signal any
      // rank received, a failure of any rank).
      const Ranks::Agreed agreed = ranks.agree(interrupt.received(), failure);
      if (!agreed.failure.empty()) {
        state_broken = false; // the state is sound; its files are what failed
        throw RunError(agreed.failure);
      }
      result.signal = agreed.signal;
      if (result.signal != 0) {
        if (checkpoint_step != c.step) last_checkpoint_agreed();
        status = "interrupted";
        message = "stopped by signal " + std::to_string(result.signal) + " after step " +
                  std::to_string(c.step);
        break;
      }
    }
    if (!result.signal) {
      progress.finish(c.time, c.step);
      if (scene.checkpoint && checkpoint_step != c.step) last_checkpoint_agreed();
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
        RunClock failed = c;
        failed.time = attempted;
        // Decomposed: gathered (collective; every rank is here, the failure agreed) in the
        // one-process format, as a checkpoint is, and written by rank 0.
        const StateArchive archive = make_archive(scene, models, failed, true, governor.most());
        if (root) write_checkpoint(options.out / "failed_state.h5", archive);
        kept += (options.out / "failed_state.h5").string();
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
