#include "fsi_app/run_state.hpp"

#include "fsi/core/error.hpp"
#include "fsi/core/format.hpp"
#include "fsi/core/parallel.hpp"
#include "fsi_app/output/checkpoint_file.hpp"

#include <algorithm>
#include <cstdint>
#include <string>

namespace fsi::app {

namespace {

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

} // namespace

StateArchive make_archive(const Scene& scene, const std::vector<std::unique_ptr<Model>>& models,
                          const RunClock& c, bool failed, int threads) {
  StateArchive a;
  a.put_integer("driver/step", c.step);
  a.put_real("driver/time", c.time);
  a.put_real("driver/next_frame", c.next_frame);
  a.put_integer("driver/frames", c.frames);
  a.put_real("driver/dt_min", c.dt_min);
  a.put_real("driver/dt_max", c.dt_max);
  a.put_real("driver/dt", scene.time.dt.value_or(0.0));
  a.put_integer("driver/threads", threads);
  a.put_integer("driver/failed", failed);
  a.put("driver/overrides", encode_strings(scene.overrides));
  a.put_integer("driver/scene_digest", static_cast<std::int64_t>(scene.digest));
  for (const auto& m : models) m->write_state(a);
  return a;
}

RunClock read_archive(const Scene& scene, std::vector<std::unique_ptr<Model>>& models,
                      const std::filesystem::path& file, std::ostream& log) {
  const StateArchive a = read_checkpoint(file);
  RunClock c;
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
      throw InputError("at t = " + significant(c.time, 6) +
                       " s, past time.end = " + significant(scene.time.end, 6) + " s of this run");
  } catch (const InputError& e) {
    throw InputError(file.string() + ": " + e.what());
  }
  if (a.integer("driver/threads") != num_threads())
    log << "note: " << file.string() << " was written with " << a.integer("driver/threads")
        << " threads, this run has " << num_threads()
        << " (results do not depend on the thread count: docs/reliability.md, Determinism)\n";
  return c;
}

} // namespace fsi::app
