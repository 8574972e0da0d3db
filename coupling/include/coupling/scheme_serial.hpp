#pragma once
// The serial schemes (EMPS-ERP-FEM paper, sec. 2.5): per evaluation the fluid takes the interface
// input, its loads go to the structure, the structure returns the interface at t + dt.
//   "css": conventional serial staggered — one evaluation per step with the predictor's input,
//          no checkpoint (explicit: the scheme has no acceleration).
//   "bgs": block Gauss-Seidel (eqs. 68-69) — F and S saved at t^n; x^0 = predictor; repeat
//          { restore F and S (from the second evaluation on); evaluate with x^i -> x~^i;
//          r^i = x~^i - x^i; stop when the measures converge or at max_iterations;
//          x^{i+1} = acceleration(x^i, x~^i) }. The last evaluation is accepted.
// The two differ only in their components (an acceleration makes the scheme implicit), so they
// are one class; the registry builds each. BasicSerialScheme<D> for D = 2 and 3.
#include "coupling/scheme.hpp"

namespace fsi::coupling {

template <int D> class BasicSerialScheme final : public BasicCouplingScheme<D> {
public:
  using typename BasicCouplingScheme<D>::Fluid;
  using typename BasicCouplingScheme<D>::Structure;

  BasicSerialScheme(std::string name, const CouplingOptions& options, Fluid& fluid,
                    Structure& structure, BasicSchemeComponents<D> components);

protected:
  BasicInterfaceMotion<D> initialize_participants(double t0) override;
  void finalize_participants() override;
  void write_participants(StateArchive& archive) const override;
  void read_participants(const StateArchive& archive) override;
  /// Implicit schemes only: the step is re-run from t^n.
  void save_checkpoint() override;
  void restore_checkpoint() override;
  BasicInterfaceMotion<D> evaluate(double t, double dt,
                                   const BasicInterfaceMotion<D>& input) override {
    return this->serial_evaluate(fluid_, structure_, t, dt, input);
  }
  bool has_residual() const override { return true; }

private:
  Fluid& fluid_;
  Structure& structure_;
};

extern template class BasicSerialScheme<2>;
extern template class BasicSerialScheme<3>;
using SerialScheme = BasicSerialScheme<2>;
using SerialScheme3 = BasicSerialScheme<3>;

} // namespace fsi::coupling
