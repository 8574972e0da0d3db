#include "coupling/interface.hpp"

#include "fsi/core/error.hpp"

#include <cassert>

namespace fsi::coupling {

InterfaceLoads InterfaceLoads::zeros(std::size_t n) {
  InterfaceLoads l;
  l.f.assign(n, Vec2::Zero());
  return l;
}

InterfaceMotion interpolate(const InterfaceMotion& a, const InterfaceMotion& b, double s) {
  assert(a.size() == b.size());
  const std::size_t n = a.size();
  InterfaceMotion m = InterfaceMotion::zeros(n);
  for (std::size_t i = 0; i < n; ++i) {
    m.x[i] = (1.0 - s) * a.x[i] + s * b.x[i];
    m.v[i] = (1.0 - s) * a.v[i] + s * b.v[i];
    m.a[i] = (1.0 - s) * a.a[i] + s * b.a[i];
  }
  return m;
}

void Participant::write_state(StateArchive&) const {
  throw RunError("checkpoint: this solver cannot write its state");
}

void Participant::read_state(const StateArchive&) {
  throw RunError("checkpoint: this solver cannot read a state");
}

} // namespace fsi::coupling
