#pragma once
// Measure "absolute": converged when ||r^i|| < tolerance (in the units of the measured quantity).
#include "coupling/convergence.hpp"

namespace fsi::coupling {

class AbsoluteConvergence final : public ConvergenceMeasure {
public:
  explicit AbsoluteConvergence(double tolerance)
      : ConvergenceMeasure("absolute"), tolerance_(tolerance) {}
  bool measure(double residual_norm, double /*magnitude*/) override {
    value_ = residual_norm;
    return residual_norm < tolerance_;
  }
  double value() const override { return value_; }
  std::string criterion() const override;

private:
  double tolerance_;
  double value_ = 0.0;
};

} // namespace fsi::coupling
