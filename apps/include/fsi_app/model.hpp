#pragma once
// What the run driver sees of one simulated part of a scene (a structure, a fluid, or a coupled
// system): advance, write its grids, answer its probes, report its statistics.
#include "fsi/core/state_archive.hpp"
#include "fsi_app/output/fields_file.hpp"
#include "fsi_app/output/json.hpp"
#include "fsi_app/particle_guard.hpp"
#include "fsi_app/ranks.hpp"
#include "fsi_app/scene.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace fsi::app {

class Model {
public:
  virtual ~Model() = default;
  /// Advances from `time` to `time + dt`; throws fsi::RunError when the run cannot go on.
  virtual void advance(double time, double dt) = 0;
  /// The largest stable step for a Courant number, for models that limit it (the fluid).
  virtual std::optional<double> stable_dt(double /*courant*/) const { return std::nullopt; }
  /// Opens the model's own logs in the output directory, before the first step. `resume`: the
  /// model was just read from a checkpoint; its logs keep the rows up to it and continue.
  virtual void open_logs(const std::filesystem::path& /*out*/, bool /*resume*/) {}
  /// Writes buffered log rows to disk (before a checkpoint, so they cover it).
  virtual void flush_logs() {}
  /// Checkpoint hooks: the full state between two steps (solvers, walls, coupler, the counters
  /// of run.json), so that a run continued from it is bitwise the uninterrupted one.
  virtual void write_state(StateArchive& archive) const = 0;
  /// Throws InputError (naming the key) when the archive does not fit this model.
  virtual void read_state(const StateArchive& archive) = 0;
  /// Declares static data (mesh connectivity) once, before the first frame (default: none).
  virtual void declare(FieldsFile& /*file*/) const {}
  /// Writes this model's grids for the current frame; `fields` lists the requested fields.
  virtual void write_frame(FieldsFile& file, const std::vector<std::string>& fields) const = 0;
  /// The probe's current value if this model owns it.
  virtual std::optional<double> probe(const ProbeSpec& probe) const = 0;
  /// Adds counts and statistics (elements, particles, iterations) to run.json.
  virtual void report(JsonObject& run) const = 0;
  /// A particle fluid's count and domain, for the driver's particle-loss guard (default: none).
  virtual std::optional<ParticleCount> particle_count() const { return std::nullopt; }
  /// The first non-finite position or velocity of what the model moves (walls, structure nodes
  /// or particles), named, e.g. "wall 'paddle' node 0 at (nan, nan) m"; the driver stops the run
  /// on it (issue 41: a wall could go NaN and the run complete).
  virtual std::optional<std::string> non_finite() const { return std::nullopt; }
  /// What the user should know since the last call (e.g. a solver's fallback); the driver
  /// prints each as `note: ...` on the log after the step.
  virtual std::vector<std::string> take_notes() { return {}; }
  /// Steps from now on decomposed over `ranks` (which outlive the model); false when this model
  /// cannot be (the run is then refused). After it, particle_count() and report() are global.
  virtual bool decompose(const Ranks& /*ranks*/) { return false; }
  /// Collective when decomposed: brings the frame's data to rank 0, where write_frame and probe
  /// read it (default, and one process: nothing to do).
  virtual void gather_frame() {}
};

} // namespace fsi::app
