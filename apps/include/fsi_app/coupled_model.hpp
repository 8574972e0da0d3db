#pragma once
// A fluid and one structure coupled through the scene's coupling scheme (css or bgs), or one of
// them alone against a recorded interface.h5 (one_way_fluid: the fluid against the recorded
// motion, the structure not solved; one_way_structure: the structure under the recorded loads,
// the fluid not solved). The part not solved stays at its initial state in fields and probes.
#include "coupling/registry.hpp"
#include "coupling/scheme.hpp"
#include "fsi_app/adapters.hpp"
#include "fsi_app/fluid_model.hpp"
#include "fsi_app/structure_model.hpp"

#include <fstream>
#include <memory>

namespace fsi::app {

class InterfaceHistory;
class InterfaceHistoryWriter;

class CoupledModel final : public Model {
public:
  /// Throws InputError (scene file and line) for a structure without interface tags, more than
  /// one structure, or coupling options the scheme rejects.
  /// one_way_*: InputError (`FILE:LINE: coupling.motion|loads: what`) for a recorded file whose
  /// node count differs from the interface's.
  explicit CoupledModel(const Scene& scene);
  ~CoupledModel() override;
  void advance(double time, double dt) override;
  /// DIR/coupling.csv: one row per coupling step (iterations, residuals of eq. 68, relaxation,
  /// convergence, wall times), flushed every 1000 rows and at the end. With
  /// coupling.record_interface also DIR/interface.h5 (row 0 at t = 0, then one row per step;
  /// not continued across a restart: refused with InputError).
  void open_logs(const std::filesystem::path& out, bool resume) override;
  void flush_logs() override;
  void declare(FieldsFile& file) const override { structure_->declare(file); }
  void write_frame(FieldsFile& file, const std::vector<std::string>& fields) const override;
  std::optional<double> probe(const ProbeSpec& probe) const override;
  void report(JsonObject& run) const override;
  /// The coupler with both participants (coupling::CouplingScheme::write_state).
  void write_state(StateArchive& archive) const override { scheme_->write_state(archive); }
  void read_state(const StateArchive& archive) override { scheme_->read_state(archive); }

  const coupling::CouplingScheme& scheme() const { return *scheme_; }
  const FluidAdapter& fluid_adapter() const { return *fluid_adapter_; }
  const StructureAdapter& structure_adapter() const { return *structure_adapter_; }
  FluidModel& fluid() { return *fluid_; }
  StructureModel& structure() { return *structure_; }

private:
  std::unique_ptr<StructureModel> structure_;
  std::unique_ptr<FluidModel> fluid_;
  std::unique_ptr<FluidAdapter> fluid_adapter_;
  std::unique_ptr<StructureAdapter> structure_adapter_;
  std::unique_ptr<coupling::CouplingScheme> scheme_;
  std::unique_ptr<std::ofstream> step_log_;
  // Recording and one-way replay.
  class FluidTap;
  std::unique_ptr<FluidTap> tap_; ///< the fluid adapter, remembering the motion it was given
  std::unique_ptr<InterfaceHistory> replay_;
  std::unique_ptr<InterfaceHistoryWriter> history_;
  bool record_ = false;
  coupling::SchemeNeeds needs_; ///< what the scheme couples (the registry's declaration)
};

} // namespace fsi::app
