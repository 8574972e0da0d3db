#pragma once
// Scheme "one_way_structure": the structure under prescribed (e.g. recorded) loads, evaluated at
// the end of each step, prescribed(t + dt), as a Newmark structure expects. No fluid is run.
#include "coupling/scheme.hpp"

namespace fsi::coupling {

class OneWayStructureScheme final : public CouplingScheme {
public:
  OneWayStructureScheme(const CouplingOptions& options, StructureSolver& structure,
                        LoadFunction prescribed, SchemeComponents components);

protected:
  InterfaceMotion initialize_participants(double t0) override;
  void finalize_participants() override;
  void write_participants(StateArchive& archive) const override { structure_.write_state(archive); }
  void read_participants(const StateArchive& archive) override { structure_.read_state(archive); }
  InterfaceMotion evaluate(double t, double dt, const InterfaceMotion& input) override;

private:
  StructureSolver& structure_;
  LoadFunction prescribed_;
};

} // namespace fsi::coupling
