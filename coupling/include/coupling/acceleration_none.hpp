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
  std::optional<double> relaxation() const override { return 1.0; }
};

} // namespace fsi::coupling
