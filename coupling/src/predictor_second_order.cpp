#include "coupling/predictor_second_order.hpp"

namespace fsi::coupling {

template <int D>
BasicInterfaceMotion<D> predict_second_order(const BasicInterfaceMotion<D>& current, double dt) {
  BasicInterfaceMotion<D> p = current; // a^ = a^n (eq. 63)
  for (std::size_t i = 0; i < p.size(); ++i) {
    p.x[i] = current.x[i] + dt * current.v[i] + 0.5 * dt * dt * current.a[i]; // eq. 64
    p.v[i] = current.v[i] + dt * current.a[i];                                // eq. 65
  }
  return p;
}

template InterfaceMotion predict_second_order(const InterfaceMotion&, double);
template InterfaceMotion3 predict_second_order(const InterfaceMotion3&, double);

} // namespace fsi::coupling
