#pragma once
// The run driver: steps the scene's models to the end time, writes frames, probes and run.json.
#include "fsi_app/model.hpp"
#include "fsi_app/scene.hpp"

#include <filesystem>
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
};

/// How a run that did not throw ended.
struct RunResult {
  int signal = 0;                   ///< SIGINT / SIGTERM that stopped it, 0 when completed
  long step = 0;                    ///< steps done
  double time = 0.0;                ///< simulated time reached, s
  std::filesystem::path checkpoint; ///< the last checkpoint written, if any
};

/// Builds the models a scene needs (structures, fluid, coupler). Throws fsi::InputError for a
/// scene that names what this build cannot simulate, before any computation.
std::vector<std::unique_ptr<Model>> build_models(const Scene& scene);

/// Runs to scene.time.end, writing checkpoints as the scene asks. On SIGINT / SIGTERM it stops
/// after the current step with a checkpoint. On fsi::RunError (a guard) it writes the failed
/// state as a last frame and as DIR/failed_state.h5, records the failure in run.json, keeps
/// everything written so far and rethrows for the caller's exit status. Throws InputError for a
/// restart checkpoint that does not fit the scene or its output files.
RunResult run_scene(const Scene& scene, std::vector<std::unique_ptr<Model>>& models,
                    const RunOptions& options);

} // namespace fsi::app
