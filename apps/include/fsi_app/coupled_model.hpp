#pragma once
// A fluid and one structure coupled through the scene's coupling scheme (css or bgs).
#include "coupling/scheme.hpp"
#include "fsi_app/adapters.hpp"
#include "fsi_app/fluid_model.hpp"
#include "fsi_app/structure_model.hpp"

#include <fstream>
#include <memory>

namespace fsi::app {

class CoupledModel final : public Model {
public:
  /// Throws InputError (scene file and line) for a structure without interface tags, more than
  /// one structure, or coupling options the scheme rejects.
  explicit CoupledModel(const Scene& scene);
  void advance(double time, double dt) override;
  /// DIR/coupling.csv: one row per coupling step (iterations, residuals of eq. 68, relaxation,
  /// convergence, wall times), flushed every 1000 rows and at the end.
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
  FluidModel& fluid() { return *fluid_; }
  StructureModel& structure() { return *structure_; }

private:
  std::unique_ptr<StructureModel> structure_;
  std::unique_ptr<FluidModel> fluid_;
  std::unique_ptr<FluidAdapter> fluid_adapter_;
  std::unique_ptr<StructureAdapter> structure_adapter_;
  std::unique_ptr<coupling::CouplingScheme> scheme_;
  std::unique_ptr<std::ofstream> step_log_;
};

} // namespace fsi::app
