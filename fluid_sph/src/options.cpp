// The fluid's user options, each declared once (key, member, range, doc): the scene reader, the
// validator and the generated reference visit them.
#include "fluid_sph/options.hpp"

#include "particles/fluid_keys.hpp"

namespace fsi::sph {

void visit_options(SphOptions& o, OptionVisitor& v) {
  particles::visit_fluid_keys(o.rho0, o.viscosity, o.dp, o.c0, o.damping_time, v);
  v.real("h_over_dp", o.h_over_dp, Range::closed(1.0, 2.0),
         "smoothing length h / dp (Wendland C2, support 2h)");
  v.choice("correction", o.correction, {{"none", Correction::none}, {"rkgc", Correction::rkgc}},
           "none: standard Riemann-SPH; rkgc: reverse kernel gradient correction on the central "
           "pressure term (eqs. 18-20)");
  v.real("wkgc_alpha", o.wkgc_alpha, Range::closed(0.0, 1.0),
         "alpha of the WKGC weighting (eqs. 21-22); 0: B unweighted");
  v.flag("free_surface", o.free_surface,
         "true: rho = max(rho_sum, rho0) at re-initialisation (free-surface flows); false: rho = "
         "rho_sum (internal flows)");
  v.flag("transport_velocity", o.transport_velocity,
         "transport-velocity shift once per advection step (eqs. 23-24; internal flows, needs "
         "free_surface: false)");
  v.real("u_ref", o.u_ref, Range::non_negative(),
         "reference speed of the advection criterion, m/s (0: sound_speed / 10)");
  v.real("advection_cfl", o.advection_cfl, Range::left_open(0.0, 1.0),
         "advection step Dt = advection_cfl h / max(|v|, sqrt(4 h |a|), u_ref, nu / h)");
  v.real("viscous_number", o.viscous_number, Range::closed(0.0, 0.5),
         "Dt <= viscous_number h^2 / nu as well (the frozen viscous term's diffusion number; "
         "0: off, the reference code's criterion alone)");
  v.flag("riemann_limiter", o.riemann_limiter,
         "eq. 5's low-dissipation limiter beta = min(3 max(u/c0, 0), 1); false: beta = 1 (settling "
         "flows, docs/fluid_sph.md)");
  v.flag("pair_dissipation", o.pair_dissipation,
         "eq. 5's Riemann dissipation between fluid pairs in the momentum equation; false: off "
         "(the reference code's viscous internal flows: Taylor-Green, Turek-Hron FSI2; the walls "
         "keep theirs, docs/fluid_sph.md)");
  v.real("acoustic_cfl", o.acoustic_cfl, Range::left_open(0.0, 1.0),
         "acoustic step dt = acoustic_cfl h / max(c0 + |v|, sqrt(4 h |a|)) (sph steps by its own "
         "criteria: time.courant is not used)");
  v.real("fixed_dt", o.fixed_dt, Range::non_negative(),
         "> 0: every acoustic step is fixed_dt, s, and the advection step Dt a whole number of "
         "them (a hydrostatic case); 0: both steps by the dual criteria");
}

} // namespace fsi::sph
