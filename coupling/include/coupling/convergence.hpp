#pragma once
// Convergence measure of an implicit scheme: one instance per measured quantity (positions,
// optionally velocities). One small class per method (convergence_relative.hpp,
// convergence_absolute.hpp), chosen by name.
#include <string>
#include <string_view>

#include "coupling/method.hpp"

namespace fsi::coupling {

class ConvergenceMeasure : public Method {
public:
  using Method::Method;
  /// Start of a coupling step: forget r^0.
  virtual void begin_step() {}
  /// Record the residual norm ||r^i|| of evaluation i = 0, 1, ... and the norm of the measured
  /// quantity ||x~^i|| (for a round-off floor); true when converged.
  virtual bool measure(double residual_norm, double magnitude) = 0;
  /// The number compared with the tolerance at the last measure() (for messages).
  virtual double value() const = 0;
  /// One-line description of the criterion, e.g. "||r||/||r0|| < 1e-4".
  virtual std::string criterion() const = 0;
};

} // namespace fsi::coupling
