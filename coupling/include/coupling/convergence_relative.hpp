#pragma once
// Measure "relative" (EMPS-ERP-FEM paper, eq. 69): converged when ||r^i|| / ||r^0|| < tolerance.
// The first evaluation (i = 0) converges only if r^0 = 0 exactly; a later one when ||r^i|| = 0.
#include "coupling/convergence.hpp"

namespace fsi::coupling {

class RelativeConvergence final : public ConvergenceMeasure {
public:
  explicit RelativeConvergence(double tolerance) : tolerance_(tolerance) {}
  std::string_view name() const override { return "relative"; }
  void begin_step() override { first_ = true; }
  bool measure(double residual_norm) override;
  double value() const override { return ratio_; }
  std::string criterion() const override;

private:
  double tolerance_;
  bool first_ = true;
  double r0_ = 0.0;
  double ratio_ = 1.0;
};

} // namespace fsi::coupling
