#include "coupling/convergence_relative.hpp"

#include <sstream>

namespace fsi::coupling {

bool RelativeConvergence::measure(double residual_norm, double magnitude) {
  if (first_) {
    first_ = false;
    r0_ = residual_norm;
    ratio_ = residual_norm == 0.0 ? 0.0 : 1.0;
    return residual_norm == 0.0;
  }
  if (residual_norm == 0.0) {
    ratio_ = 0.0;
    return true;
  }
  ratio_ = residual_norm / r0_; // eq. 69
  return ratio_ < tolerance_ || residual_norm <= roundoff_floor * magnitude;
}

std::string RelativeConvergence::criterion() const {
  std::ostringstream s;
  s << "||r||/||r0|| < " << tolerance_;
  return s.str();
}

} // namespace fsi::coupling
