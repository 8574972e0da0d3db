#pragma once
// The run driver: steps the scene's models to the end time, writes frames, probes and run.json.
#include "fsi_app/model.hpp"
#include "fsi_app/scene.hpp"

#include <filesystem>
#include <functional>
#include <memory>
#include <ostream>
#include <vector>

namespace fsi::app {

struct RunOptions {
  std::filesystem::path out; ///< output directory, created if missing
  bool terminal = false;     ///< live progress line instead of periodic log lines
  std::ostream* log = nullptr;
  /// A checkpoint to continue from (empty: start at t = 0). The files in `out` are cut back to
  /// it and continued (docs/reliability.md).
  std::filesystem::path restart;
  /// A fresh run into a folder that holds another run's files deletes exactly those files
  /// (fields.h5, fields.xmf, probes.csv, run.json, coupling.csv, interface.h5,
  /// checkpoint_*.h5, failed_state.h5); without it such a folder is refused (InputError).
  bool overwrite = false;
  /// Called after every step with (time, step), e.g. the Python module's progress callback.
  std::function<void(double, long)> on_step = nullptr;
  /// The processes of the run (null: one); decomposed, files are written by rank 0 only.
  const Ranks* ranks = nullptr;
};

/// How a run that did not throw ended.
struct RunResult {
  int signal = 0;                   ///< SIGINT / SIGTERM that stopped it, 0 when completed
  long step = 0;                    ///< steps done
  double time = 0.0;                ///< simulated time reached, s
  std::filesystem::path checkpoint; ///< the last checkpoint written, if any
};

/// Builds the models a scene needs (structures, fluid, coupler). Throws fsi::InputError for a
/// scene that names what this build cannot simulate, before any computation. `ranks`: the
/// processes run_scene decomposes the models over (a particle fluid's share is built on each).
std::vector<std::unique_ptr<Model>> build_models(const Scene& scene,
                                                 const Ranks& ranks = OneProcess());

/// The input checks build_models makes, through each plug-in's `validate`, without building the
/// solvers (`fsi check`): the same InputError for the same scene.
void check_models(const Scene& scene);

/// The most steps a run may take (1e9): more is refused, see run_scene.
double max_steps();

/// Runs to scene.time.end, writing checkpoints as the scene asks. On SIGINT / SIGTERM it stops
/// after the current step with a checkpoint. On fsi::RunError (a guard) it writes the failed
/// state as a last frame and as DIR/failed_state.h5, records the failure in run.json, keeps
/// everything written so far and rethrows for the caller's exit status. Throws InputError for a
/// restart checkpoint that does not fit the scene or its output files, a fixed step that needs
/// more than max_steps() steps, an output folder that another run holds (flock on DIR/.lock) or
/// that holds another run's files (unless options.overwrite), or that cannot be written.
/// A Courant step so small that more than max_steps() steps would remain is a RunError.
RunResult run_scene(const Scene& scene, std::vector<std::unique_ptr<Model>>& models,
                    const RunOptions& options);

} // namespace fsi::app
