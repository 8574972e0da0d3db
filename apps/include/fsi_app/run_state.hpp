#pragma once
// The run driver's checkpointed state: its clock under "driver/" beside the models' states, the
// checks a restart makes of a checkpoint against the scene (docs/reliability.md, "Restart").
#include "fsi/core/state_archive.hpp"
#include "fsi_app/model.hpp"
#include "fsi_app/scene.hpp"

#include <filesystem>
#include <limits>
#include <memory>
#include <ostream>
#include <vector>

namespace fsi::app {

/// The driver's own state, checkpointed under "driver/" beside the models'.
struct RunClock {
  long step = 0;
  double time = 0.0, next_frame = 0.0;
  int frames = 0;
  double dt_min = std::numeric_limits<double>::infinity(), dt_max = 0.0;
};

/// The driver's clock, the run's settings (dt, the asked `threads`, overrides, scene digest) and
/// every model's state; `failed`: the state of a failed step (kept for inspection, refused on
/// restart).
StateArchive make_archive(const Scene& scene, const std::vector<std::unique_ptr<Model>>& models,
                          const RunClock& clock, bool failed, int threads);

/// Reads the driver's state and the models' from a restart checkpoint. Throws InputError
/// (`FILE: what`) for a failed step's state, another time step, other overrides (time.end
/// aside), an edited scene or a time past time.end; notes another thread count on `log`.
RunClock read_archive(const Scene& scene, std::vector<std::unique_ptr<Model>>& models,
                      const std::filesystem::path& file, std::ostream& log);

} // namespace fsi::app
