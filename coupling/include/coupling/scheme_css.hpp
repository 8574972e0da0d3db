#pragma once
// Scheme "css": conventional serial staggered. Per step: predict the interface (predictor
// option), fluid step against it, project loads, structure step. One evaluation, no checkpoint.
#include "coupling/scheme.hpp"

namespace fsi::coupling {

class CssScheme final : public CouplingScheme {
public:
  CssScheme(const CouplingOptions& options, FluidSolver& fluid, StructureSolver& structure,
            SchemeComponents components);

protected:
  InterfaceMotion initialize_participants(double t0) override;
  void finalize_participants() override;
  void write_participants(StateArchive& archive) const override {
    fluid_.write_state(archive);
    structure_.write_state(archive);
  }
  void read_participants(const StateArchive& archive) override {
    fluid_.read_state(archive);
    structure_.read_state(archive);
  }
  InterfaceMotion evaluate(double t, double dt, const InterfaceMotion& input) override {
    return serial_evaluate(fluid_, structure_, t, dt, input);
  }

private:
  FluidSolver& fluid_;
  StructureSolver& structure_;
};

} // namespace fsi::coupling
