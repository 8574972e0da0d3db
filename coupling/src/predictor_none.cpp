#include "coupling/predictor_none.hpp"

namespace fsi::coupling {

InterfaceMotion NoPredictor::predict(const InterfaceMotion& current, double /*dt*/) const {
  return current;
}

} // namespace fsi::coupling
