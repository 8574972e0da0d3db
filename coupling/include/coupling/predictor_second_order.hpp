#pragma once
// Predictor "second_order" (EMPS-ERP-FEM paper, eqs. 63-65):
//   a^ = a^n,  x^ = x^n + dt v^n + dt^2/2 a^n,  v^ = v^n + dt a^n.
// This is Newmark average acceleration (beta = 1/4, gamma = 1/2) with a^{n+1} = a^n, so the
// predicted triple is kinematically consistent with such a structure; relaxation keeps it so.
#include "coupling/predictor.hpp"

namespace fsi::coupling {

/// Eqs. 63-65 applied node by node (D = 2 and 3).
template <int D>
BasicInterfaceMotion<D> predict_second_order(const BasicInterfaceMotion<D>& current, double dt);

extern template InterfaceMotion predict_second_order(const InterfaceMotion&, double);
extern template InterfaceMotion3 predict_second_order(const InterfaceMotion3&, double);

template <int D> class BasicSecondOrderPredictor final : public BasicPredictor<D> {
public:
  BasicSecondOrderPredictor() : BasicPredictor<D>("second_order") {}
  BasicInterfaceMotion<D> predict(const BasicInterfaceMotion<D>& current,
                                  double dt) const override {
    return predict_second_order(current, dt);
  }
};
using SecondOrderPredictor = BasicSecondOrderPredictor<2>;
using SecondOrderPredictor3 = BasicSecondOrderPredictor<3>;

} // namespace fsi::coupling
