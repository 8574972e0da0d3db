#include "coupling/scheme_one_way_fluid.hpp"

namespace fsi::coupling {

template <int D>
BasicOneWayFluidScheme<D>::BasicOneWayFluidScheme(const CouplingOptions& options, Fluid& fluid,
                                                  BasicMotionFunction<D> prescribed,
                                                  BasicSchemeComponents<D> components)
    : BasicCouplingScheme<D>("one_way_fluid", options, std::move(components)), fluid_(fluid),
      prescribed_(std::move(prescribed)) {}

template <int D>
BasicInterfaceMotion<D> BasicOneWayFluidScheme<D>::initialize_participants(double t0) {
  this->time_fluid([&] { fluid_.initialize(); });
  return prescribed_(t0);
}

template <int D> void BasicOneWayFluidScheme<D>::finalize_participants() {
  fluid_.finalize();
}

template <int D>
BasicInterfaceMotion<D> BasicOneWayFluidScheme<D>::evaluate(double t, double dt,
                                                            const BasicInterfaceMotion<D>& input) {
  this->run_fluid(fluid_, t, dt,
                  [&](double s) { return s == 1.0 ? input : prescribed_(t + s * dt); });
  return input;
}

template class BasicOneWayFluidScheme<2>;
template class BasicOneWayFluidScheme<3>;

} // namespace fsi::coupling
