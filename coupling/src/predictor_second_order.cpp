#include "coupling/predictor_second_order.hpp"

namespace fsi::coupling {

InterfaceMotion predict_second_order(const InterfaceMotion& current, double dt) {
  InterfaceMotion p = current; // a^ = a^n (eq. 63)
  for (std::size_t i = 0; i < p.size(); ++i) {
    p.x[i] = current.x[i] + dt * current.v[i] + 0.5 * dt * dt * current.a[i]; // eq. 64
    p.v[i] = current.v[i] + dt * current.a[i];                                // eq. 65
  }
  return p;
}

} // namespace fsi::coupling
