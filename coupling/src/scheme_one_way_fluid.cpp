#include "coupling/scheme_one_way_fluid.hpp"

namespace fsi::coupling {

OneWayFluidScheme::OneWayFluidScheme(const CouplingOptions& options, FluidSolver& fluid,
                                     MotionFunction prescribed, SchemeComponents components)
    : CouplingScheme("one_way_fluid", options, std::move(components)), fluid_(fluid),
      prescribed_(std::move(prescribed)) {}

InterfaceMotion OneWayFluidScheme::initialize_participants(double t0) {
  time_fluid([&] { fluid_.initialize(); });
  return prescribed_(t0);
}

void OneWayFluidScheme::finalize_participants() {
  fluid_.finalize();
}

InterfaceMotion OneWayFluidScheme::evaluate(double t, double dt, const InterfaceMotion& input) {
  run_fluid(fluid_, t, dt, [&](double s) { return s == 1.0 ? input : prescribed_(t + s * dt); });
  return input;
}

} // namespace fsi::coupling
