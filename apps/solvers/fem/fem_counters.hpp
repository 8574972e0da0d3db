#pragma once
// The Newton and linear-solver counts of one FE structure over a run (T6 or T10): summed per
// step, checkpointed, and reported in run.json.
#include "fsi/core/state_archive.hpp"
#include "fsi_app/output/json.hpp"
#include "structure_fem/newton_raphson.hpp"

#include <string>

namespace fsi::app::fem_plugin {

struct FemCounters {
  long newton_iterations = 0, steps = 0;
  int newton_max = 0;
  long newton_halvings = 0, steps_with_halvings = 0; ///< Newton safeguard (Structure::newton)
  long substepped_steps = 0, substeps = 0;           ///< retried steps, their sub-steps
  long roundoff_stops = 0;    ///< Newton solves ended at the round-off floor (fem::NewtonOptions)
  long lu_fallbacks = 0;      ///< factorisations done by LU (fem::LinearSolverKind::ldlt_or_lu)
  long lu_fallbacks_seen = 0; ///< the structure's own count at the last step

  /// One step's report; `fallbacks`: the structure's LU count after it.
  void add(const fem::StepReport& report, long fallbacks);
  /// Under "run/structures/<name>/".
  void write(StateArchive& archive, const std::string& name) const;
  void read(const StateArchive& archive, const std::string& name);
  /// "structure_<name>" of run.json, with the mesh's node and element counts.
  void report(JsonObject& run, const std::string& name, std::size_t nodes,
              std::size_t elements) const;
};

} // namespace fsi::app::fem_plugin
