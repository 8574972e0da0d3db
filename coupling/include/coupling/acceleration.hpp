#pragma once
// Acceleration of the block Gauss-Seidel fixed point x = H(x) = S(F(x)) (eq. 68).
//
// The coupling vector stacks the interface positions, velocities and accelerations (layout
// documented in scheme.hpp). Each method is one small class in its own file, chosen by name:
// "none" (plain BGS), "constant", "aitken", "iqn-ils".
//
// Calls per coupling step: begin_step(scale); update(x^0, x~^0) -> x^1; update(x^1, x~^1) -> x^2;
// ...; end_step(converged). Inner products and norms inside a method use the scaled vector
// diag(scale) r so that positions, velocities and accelerations are comparable; the update itself
// is made in the unscaled variables.
#include <optional>
#include <string>
#include <string_view>

#include <Eigen/Core>

#include "coupling/method.hpp"

namespace fsi {
class StateArchive;
}

namespace fsi::coupling {

class Acceleration : public Method {
public:
  using Method::Method;

  /// Start of a coupling step. `scale` holds one positive weight per entry of the coupling vector
  /// (empty: all ones). It may change between steps (for example when dt changes).
  virtual void begin_step(const Eigen::VectorXd& /*scale*/) {}
  /// Next input x^{i+1} from the input x^i of evaluation i and its output x~^i = H(x^i).
  virtual void update(const Eigen::VectorXd& x, const Eigen::VectorXd& x_tilde,
                      Eigen::VectorXd& x_next) = 0;
  /// End of the coupling step (converged or abandoned at max_iterations).
  virtual void end_step(bool /*converged*/) {}
  /// Relaxation factor of the last update(); empty if it was not a relaxation x + omega r.
  virtual std::optional<double> relaxation() const = 0;
  /// Checkpoint of what carries over from one coupling step to the next (keys `prefix` + name);
  /// read_state() continues bitwise. Called between steps only. Default: nothing carries over.
  virtual void write_state(StateArchive& /*archive*/, const std::string& /*prefix*/) const {}
  virtual void read_state(const StateArchive& /*archive*/, const std::string& /*prefix*/) {}
};

} // namespace fsi::coupling
