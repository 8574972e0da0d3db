#include "coupling/interface.hpp"

#include "fsi/core/error.hpp"

#include <cassert>

namespace fsi::coupling {

template <int D> BasicInterfaceLoads<D> BasicInterfaceLoads<D>::zeros(std::size_t n) {
  BasicInterfaceLoads l;
  l.f.assign(n, VecD<D>::Zero());
  return l;
}

template struct BasicInterfaceLoads<2>;
template struct BasicInterfaceLoads<3>;

template <int D>
BasicInterfaceMotion<D> interpolate(const BasicInterfaceMotion<D>& a,
                                    const BasicInterfaceMotion<D>& b, double s) {
  assert(a.size() == b.size());
  const std::size_t n = a.size();
  auto m = BasicInterfaceMotion<D>::zeros(n);
  for (std::size_t i = 0; i < n; ++i) {
    m.x[i] = (1.0 - s) * a.x[i] + s * b.x[i];
    m.v[i] = (1.0 - s) * a.v[i] + s * b.v[i];
    m.a[i] = (1.0 - s) * a.a[i] + s * b.a[i];
  }
  return m;
}

template InterfaceMotion interpolate(const InterfaceMotion&, const InterfaceMotion&, double);
template InterfaceMotion3 interpolate(const InterfaceMotion3&, const InterfaceMotion3&, double);

void Participant::write_state(StateArchive&) const {
  throw RunError("checkpoint: this solver cannot write its state");
}

void Participant::read_state(const StateArchive&) {
  throw RunError("checkpoint: this solver cannot read a state");
}

} // namespace fsi::coupling
