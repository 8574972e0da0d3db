#pragma once
// Acceleration "constant": x^{i+1} = x^i + omega (x~^i - x^i), omega fixed.
#include "coupling/acceleration.hpp"

namespace fsi::coupling {

class ConstantRelaxation final : public Acceleration {
public:
  explicit ConstantRelaxation(double omega) : Acceleration("constant"), omega_(omega) {}
  void begin_step(const Eigen::VectorXd&) override {}
  void update(const Eigen::VectorXd& x, const Eigen::VectorXd& x_tilde,
              Eigen::VectorXd& x_next) override {
    x_next = x + omega_ * (x_tilde - x);
  }
  void end_step(bool) override {}
  /// Nothing carries over between steps.
  void write_state(StateArchive&, const std::string&) const override {}
  void read_state(const StateArchive&, const std::string&) override {}
  std::optional<double> relaxation() const override { return omega_; }

private:
  double omega_;
};

} // namespace fsi::coupling
