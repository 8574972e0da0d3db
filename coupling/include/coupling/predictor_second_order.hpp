#pragma once
// Predictor "second_order" (EMPS-ERP-FEM paper, eqs. 63-65):
//   a^ = a^n,  x^ = x^n + dt v^n + dt^2/2 a^n,  v^ = v^n + dt a^n.
// This is Newmark average acceleration (beta = 1/4, gamma = 1/2) with a^{n+1} = a^n, so the
// predicted triple is kinematically consistent with such a structure; relaxation keeps it so.
#include "coupling/predictor.hpp"

namespace fsi::coupling {

/// Eqs. 63-65 applied node by node.
InterfaceMotion predict_second_order(const InterfaceMotion& current, double dt);

class SecondOrderPredictor final : public Predictor {
public:
  SecondOrderPredictor() : Predictor("second_order") {}
  InterfaceMotion predict(const InterfaceMotion& current, double dt) const override {
    return predict_second_order(current, dt);
  }
};

} // namespace fsi::coupling
