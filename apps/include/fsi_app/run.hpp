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
};

/// Builds the models a scene needs (structures, fluid, coupler). Throws fsi::InputError for a
/// scene that names what this build cannot simulate, before any computation.
std::vector<std::unique_ptr<Model>> build_models(const Scene& scene);

/// Runs to scene.time.end. On fsi::RunError, run.json records the failure and everything written
/// so far stays on disk; the error is rethrown for the caller's exit status.
void run_scene(const Scene& scene, std::vector<std::unique_ptr<Model>>& models,
               const RunOptions& options);

} // namespace fsi::app
