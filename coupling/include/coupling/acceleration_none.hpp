#pragma once
// Acceleration "none": plain block Gauss-Seidel, x^{i+1} = x~^i.
#include "coupling/acceleration.hpp"

namespace fsi::coupling {

class NoAcceleration final : public Acceleration {
public:
  std::string_view name() const override { return "none"; }
  void begin_step(const Eigen::VectorXd&) override {}
  void update(const Eigen::VectorXd&, const Eigen::VectorXd& x_tilde,
              Eigen::VectorXd& x_next) override {
    x_next = x_tilde;
  }
  void end_step(bool) override {}
  /// Nothing carries over between steps.
  void write_state(StateArchive&, const std::string&) const override {}
  void read_state(const StateArchive&, const std::string&) override {}
  std::optional<double> relaxation() const override { return 1.0; }
};

} // namespace fsi::coupling
