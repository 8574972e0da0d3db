#pragma once
// Scheme "one_way_fluid": the fluid against a prescribed interface motion. Sub-step k of the
// step [t, t + dt] gets prescribed(t + k dt / m) (exact, not interpolated). The loads (averaged
// over the sub-steps) are available from interface_loads() for output; no structure is run.
#include "coupling/scheme.hpp"

namespace fsi::coupling {

class OneWayFluidScheme final : public CouplingScheme {
public:
  OneWayFluidScheme(const CouplingOptions& options, FluidSolver& fluid, MotionFunction prescribed,
                    SchemeComponents components);

protected:
  InterfaceMotion initialize_participants(double t0) override;
  void finalize_participants() override;
  void write_participants(StateArchive& archive) const override { fluid_.write_state(archive); }
  void read_participants(const StateArchive& archive) override { fluid_.read_state(archive); }
  InterfaceMotion first_input(double t, double dt) override { return prescribed_(t + dt); }
  InterfaceMotion evaluate(double t, double dt, const InterfaceMotion& input) override;

private:
  FluidSolver& fluid_;
  MotionFunction prescribed_;
};

} // namespace fsi::coupling
