#pragma once
// The Riemann-SPH options shared by the dam-break benchmark and the surge-front run: water,
// nu = 1e-6, gravity, rkgc with the hydrostatic-case alpha = 0.3 (method notes), dual-criteria
// steps.
#include "fluid_sph/options.hpp"

namespace fsi::sph {

inline SphOptions dam_break_options(double dp, double c0, double u_ref, const Vec2& lo,
                                    const Vec2& hi) {
  SphOptions o;
  o.rho0 = 1000.0;
  o.dp = dp;
  o.c0 = c0;
  o.u_ref = u_ref;
  o.viscosity = 1e-6;
  o.gravity = {0.0, -9.81};
  o.correction = Correction::rkgc;
  o.wkgc_alpha = 0.3;
  o.domain_min = lo;
  o.domain_max = hi;
  return o;
}

} // namespace fsi::sph
