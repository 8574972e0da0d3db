#pragma once
// Predictor "none": keep x^n, v^n, a^n (the paper's CSS "without predictor").
#include "coupling/predictor.hpp"

namespace fsi::coupling {

template <int D> class BasicNoPredictor final : public BasicPredictor<D> {
public:
  BasicNoPredictor() : BasicPredictor<D>("none") {}
  BasicInterfaceMotion<D> predict(const BasicInterfaceMotion<D>& current,
                                  double /*dt*/) const override {
    return current;
  }
};
using NoPredictor = BasicNoPredictor<2>;
using NoPredictor3 = BasicNoPredictor<3>;

} // namespace fsi::coupling
