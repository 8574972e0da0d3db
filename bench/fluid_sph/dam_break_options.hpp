#pragma once
// The Riemann-SPH options shared by the dam-break benchmarks (2-D, 3-D) and the surge-front run:
// water, nu = 1e-6, gravity, rkgc with the hydrostatic-case alpha = 0.3 (method notes),
// dual-criteria steps.
#include "fluid_sph/options.hpp"

namespace fsi::sph {

/// Gravity -9.81 along the last axis (y in 2-D, z in 3-D).
template <int D>
BasicSphOptions<D> dam_break_options(double dp, double c0, double u_ref, const VecD<D>& lo,
                                     const VecD<D>& hi) {
  BasicSphOptions<D> o;
  o.rho0 = 1000.0;
  o.dp = dp;
  o.c0 = c0;
  o.u_ref = u_ref;
  o.viscosity = 1e-6;
  o.gravity = VecD<D>::Zero();
  o.gravity[D - 1] = -9.81;
  o.correction = Correction::rkgc;
  o.wkgc_alpha = 0.3;
  o.domain_min = lo;
  o.domain_max = hi;
  return o;
}

} // namespace fsi::sph
