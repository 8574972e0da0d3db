#pragma once
// Interface predictor: the first guess of the interface state at t^{n+1} from the state at t^n.
// One small class per method (predictor_none.hpp, predictor_second_order.hpp), chosen by name.
#include <string_view>

#include "coupling/interface.hpp"
#include "coupling/method.hpp"

namespace fsi::coupling {

/// BasicPredictor<D> for D = 2 (Predictor) and 3 (Predictor3).
template <int D> class BasicPredictor : public Method {
public:
  using Method::Method;
  /// Predicted interface state at t^n + dt from the accepted state `current` at t^n.
  virtual BasicInterfaceMotion<D> predict(const BasicInterfaceMotion<D>& current,
                                          double dt) const = 0;
};
using Predictor = BasicPredictor<2>;
using Predictor3 = BasicPredictor<3>;

} // namespace fsi::coupling
