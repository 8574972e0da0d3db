#pragma once
// Predictor "none": keep x^n, v^n, a^n (the paper's CSS "without predictor").
#include "coupling/predictor.hpp"

namespace fsi::coupling {

class NoPredictor final : public Predictor {
public:
  NoPredictor() : Predictor("none") {}
  InterfaceMotion predict(const InterfaceMotion& current, double dt) const override;
};

} // namespace fsi::coupling
