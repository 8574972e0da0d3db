#pragma once
// What the FE structure's part does alike for T6 and T10: one Newmark step with the Newton and
// linear-solver counts summed per step, the checkpoint, run.json and the finite guard.
#include "fsi/core/state_archive.hpp"
#include "fsi_app/output/json.hpp"
#include "fsi_app/solver_plugin.hpp"
#include "structure_fem/newton_raphson.hpp"
#include "structure_fem/structure.hpp"

#include <memory>
#include <string>

namespace fsi::app::fem_plugin {

struct FemCounters {
  long newton_iterations = 0, steps = 0;
  int newton_max = 0;
  long newton_halvings = 0, steps_with_halvings = 0; ///< Newton safeguard (Structure::newton)
  long substepped_steps = 0, substeps = 0;           ///< retried steps, their sub-steps
  long roundoff_stops = 0;    ///< Newton solves ended at the round-off floor (fem::NewtonOptions)
  long guess_retries = 0;     ///< Newton solves retried from u^n + dt v^n (fem::StepReport)
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

/// A structure part holding its BasicStructure<Family> and counters.
template <class Family> class BasicFemPart : public StructurePart {
public:
  BasicFemPart(std::string name, std::unique_ptr<fem::BasicStructure<Family>> structure);
  /// One step of the structure's own clock; RunError names the structure.
  void advance(double time, double dt) override;
  std::optional<std::string> non_finite() const override;
  void report(JsonObject& run) const override;
  /// The structure and its Newton counters under "structures/<name>/".
  void write_state(StateArchive& archive) const override;
  void read_state(const StateArchive& archive) override;

  fem::BasicStructure<Family>& structure() { return *structure_; }
  const fem::BasicStructure<Family>& structure() const { return *structure_; }

protected:
  std::unique_ptr<fem::BasicStructure<Family>> structure_;
  FemCounters counters_;
};

extern template class BasicFemPart<fem::T6>;
extern template class BasicFemPart<fem::T10>;

} // namespace fsi::app::fem_plugin
