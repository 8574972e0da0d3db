#pragma once
// The keys every particle fluid declares alike, so that one scene runs with either fluid by
// `fluid.type` alone: density, viscosity, l0 (the spacing), sound_speed, damping_time.
#include "fsi/core/options.hpp"

namespace fsi::particles {

inline void visit_fluid_keys(double& density, double& viscosity, double& l0, double& sound_speed,
                             double& damping_time, OptionVisitor& v) {
  v.required("density", density, Range::positive(), "rho, kg/m^3");
  v.real("viscosity", viscosity, Range::non_negative(),
         "kinematic viscosity nu, m^2/s; 0 skips the viscous loop");
  v.required("l0", l0, Range::positive(), "initial particle spacing, m (sph: dp)");
  v.required("sound_speed", sound_speed, Range::positive(),
             "artificial sound speed, m/s (emps: c of eq. 15; sph: c0 of p = c0^2 (rho - rho0), "
             "eq. 2)");
  v.real("damping_time", damping_time, Range::non_negative(),
         "initial damping phase T_d: velocities damped at a rate 20/T_d (1 - t/T_d) (quiet "
         "hydrostatic starts), s");
}

} // namespace fsi::particles
