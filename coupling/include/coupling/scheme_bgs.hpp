#pragma once
// Scheme "bgs": block Gauss-Seidel (EMPS-ERP-FEM paper, eqs. 68-69). Per step: save F and S;
// x^0 = predictor; repeat { restore F and S to t^n (from the second evaluation on); F with x^i;
// S with F's loads -> x~^i; r^i = x~^i - x^i; stop when the measures converge or at
// max_iterations; x^{i+1} = acceleration(x^i, x~^i) }. The solvers' last evaluation is accepted.
#include "coupling/scheme.hpp"

namespace fsi::coupling {

class BgsScheme final : public CouplingScheme {
public:
  BgsScheme(const CouplingOptions& options, FluidSolver& fluid, StructureSolver& structure,
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
  void save_checkpoint() override;
  void restore_checkpoint() override;
  InterfaceMotion evaluate(double t, double dt, const InterfaceMotion& input) override {
    return serial_evaluate(fluid_, structure_, t, dt, input);
  }

private:
  FluidSolver& fluid_;
  StructureSolver& structure_;
};

} // namespace fsi::coupling
