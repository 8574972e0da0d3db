#pragma once
// Measure "relative" (EMPS-ERP-FEM paper, eq. 69): converged when ||r^i|| / ||r^0|| < tolerance.
// Round-off floor: also converged when ||r^i|| <= 1e-14 ||x~^i|| (i >= 1), since a residual at
// the round-off level of the positions cannot be reduced further (with a good predictor r^0 can
// itself be within a few hundred ulps, and eq. 69 alone would then never be met).
// The first evaluation (i = 0) converges only if r^0 = 0 exactly.
#include "coupling/convergence.hpp"

namespace fsi::coupling {

class RelativeConvergence final : public ConvergenceMeasure {
public:
  explicit RelativeConvergence(double tolerance)
      : ConvergenceMeasure("relative"), tolerance_(tolerance) {}
  void begin_step() override { first_ = true; }
  bool measure(double residual_norm, double magnitude) override;
  static constexpr double roundoff_floor = 1e-14;
  double value() const override { return ratio_; }
  std::string criterion() const override;

private:
  double tolerance_;
  bool first_ = true;
  double r0_ = 0.0;
  double ratio_ = 1.0;
};

} // namespace fsi::coupling
