#include "fsi_app/run.hpp"

#include "fsi/core/error.hpp"
#include "fsi/core/parallel.hpp"
#include "fsi_app/output/probes_csv.hpp"
#include "fsi_app/progress.hpp"
#include "fsi_app/version.hpp"

#include <chrono>
#include <cmath>
#include <ctime>
#include <fstream>
#include <limits>

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

class Recorder {
public:
  Recorder(const Scene& scene, const std::vector<std::unique_ptr<Model>>& models,
           const std::filesystem::path& out)
      : scene_(scene), models_(models), fields_(out / "fields.h5", out / "fields.xmf"),
        probes_(out / "probes.csv", probe_names(scene)) {
    for (const auto& m : models_) m->open_logs(out), m->declare(fields_);
  }

  void frame(double time) {
    fields_.begin_frame(time);
    for (const auto& m : models_) m->write_frame(fields_, scene_.output.fields);
    fields_.end_frame();
    std::vector<double> values;
    for (const auto& p : scene_.output.probes) values.push_back(probe(p));
    probes_.row(time, values);
  }

  int frames() const { return fields_.frames(); }

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
  FieldsFile fields_;
  ProbesCsv probes_;
};

} // namespace

void run_scene(const Scene& scene, std::vector<std::unique_ptr<Model>>& models,
               const RunOptions& options) {
  std::filesystem::create_directories(options.out);
  std::ostream& log = *options.log;
  const auto start = std::chrono::system_clock::now();
  const auto wall_start = std::chrono::steady_clock::now();
  long step = 0;
  double time = 0.0, dt_min = std::numeric_limits<double>::infinity(), dt_max = 0.0;
  std::string status = "completed", message;
  int frames = 0;
  // The step: fixed (time = step * dt exactly, frames every round(interval / dt) steps), or the
  // smallest stable step of the models for the Courant number, shortened to land on frames.
  auto next_dt = [&](double next_frame) {
    if (scene.time.dt) return *scene.time.dt;
    double dt = std::numeric_limits<double>::infinity();
    for (const auto& m : models)
      if (auto s = m->stable_dt(*scene.time.courant)) dt = std::min(dt, *s);
    return std::min(dt, next_frame - time);
  };
  try {
    Recorder recorder(scene, models, options.out);
    Progress progress(scene.time.end, options.terminal, log);
    recorder.frame(0.0);
    frames = recorder.frames();
    const double end = scene.time.end, interval = scene.output.interval;
    const long fixed_total =
        scene.time.dt ? std::lround(std::ceil(end / *scene.time.dt - 1e-9)) : 0;
    const long fixed_per_frame =
        scene.time.dt ? std::max(1L, std::lround(interval / *scene.time.dt)) : 0;
    double next_frame = std::min(interval, end);
    while (scene.time.dt ? step < fixed_total : time < end * (1.0 - 1e-12)) {
      const double dt = next_dt(next_frame);
      for (auto& m : models) m->advance(time, dt);
      ++step;
      time = scene.time.dt ? static_cast<double>(step) * dt : time + dt;
      dt_min = std::min(dt_min, dt), dt_max = std::max(dt_max, dt);
      const bool frame = scene.time.dt ? step % fixed_per_frame == 0 || step == fixed_total
                                       : time >= next_frame * (1.0 - 1e-12);
      if (frame) {
        recorder.frame(time);
        frames = recorder.frames();
        next_frame = std::min(next_frame + interval, end);
      }
      progress.update(time, step);
    }
    progress.finish(time, step);
  } catch (const RunError& e) {
    status = "failed";
    message = e.what();
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
      .add("steps", static_cast<long long>(step))
      .add("simulated_time", time)
      .add("dt_min", dt_min)
      .add("dt_max", dt_max)
      .add("frames", frames);
  for (const auto& m : models) m->report(run);
  std::ofstream(options.out / "run.json") << run.str() << '\n';
  if (status != "completed") throw RunError(message);
}

} // namespace fsi::app
