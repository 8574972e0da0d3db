#pragma once
// Acceleration "none": plain block Gauss-Seidel, x^{i+1} = x~^i.
#include "coupling/acceleration.hpp"

namespace fsi::coupling {

class NoAcceleration final : public Acceleration {
public:
  NoAcceleration() : Acceleration("none") {}
  void update(const Eigen::VectorXd&, const Eigen::VectorXd& x_tilde,
              Eigen::VectorXd& x_next) override {
    x_next = x_tilde;
  }
  std::optional<double> relaxation() const override { return 1.0; }
};

} // namespace fsi::coupling
