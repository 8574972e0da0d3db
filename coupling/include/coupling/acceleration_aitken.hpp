#pragma once
// Acceleration "aitken": dynamic relaxation (Kuettler & Wall 2008, Comput. Mech. 43:61-72).
//   r^i = x~^i - x^i,  x^{i+1} = x^i + omega_i r^i,
//   omega_i = -omega_{i-1} (r^{i-1} . (r^i - r^{i-1})) / ||r^i - r^{i-1}||^2   (i >= 1),
// inner products on the scaled vector. First factor of a step (i = 0):
//   omega_0 = sign(omega_prev) min(omega_init, |omega_prev|), omega_prev = last factor of the
//   previous step (omega_init on the first step), as in preCICE's AitkenAcceleration.
// Clamp: |omega_i| <= omega_max (sign kept). If r^i = r^{i-1} the previous factor is kept.
// On a scalar linear map the second update lands on the fixed point.
#include "coupling/acceleration.hpp"

namespace fsi::coupling {

class AitkenRelaxation final : public Acceleration {
public:
  AitkenRelaxation(double omega_init, double omega_max);
  void begin_step(const Eigen::VectorXd& scale) override;
  void update(const Eigen::VectorXd& x, const Eigen::VectorXd& x_tilde,
              Eigen::VectorXd& x_next) override;
  void write_state(StateArchive& archive, const std::string& prefix) const override;
  void read_state(const StateArchive& archive, const std::string& prefix) override;
  std::optional<double> relaxation() const override { return omega_; }

private:
  double omega_init_, omega_max_;
  double omega_;           // factor of the last update
  Eigen::VectorXd scale_;  // empty: ones
  Eigen::VectorXd r_prev_; // scaled residual of the previous iteration
  int iteration_ = 0;
};

} // namespace fsi::coupling
