// The fluid's user options, each declared once (key, member, range, doc): the scene reader, the
// validator and the generated reference visit them; validate() checks them together.
#include "fluid_sph/options.hpp"

#include "shared.hpp"

#include "fsi/core/error.hpp"
#include "particles/fluid_keys.hpp"

namespace fsi::sph {

template <int D> void visit_options(BasicSphOptions<D>& o, OptionVisitor& v) {
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

template void visit_options<2>(SphOptions&, OptionVisitor&);
template void visit_options<3>(SphOptions3&, OptionVisitor&);

std::string to_string(Correction c) {
  return c == Correction::none ? "none" : "rkgc";
}

template <int D> void BasicSphOptions<D>::validate() const {
  const auto fail = [](const std::string& key, double v, const std::string& range) {
    throw InputError("fluid_sph: " + key + " = " + fmt(v) + ", allowed " + range);
  };
  if (!(rho0 > 0.0)) fail("rho0", rho0, "> 0");
  if (!(c0 > 0.0)) fail("c0", c0, "> 0");
  if (!(dp > 0.0)) fail("dp", dp, "> 0");
  if (!(h_over_dp >= 1.0 && h_over_dp <= 2.0)) fail("h_over_dp", h_over_dp, "[1, 2]");
  if (!(viscosity >= 0.0)) fail("viscosity", viscosity, ">= 0");
  if (!(wkgc_alpha >= 0.0 && wkgc_alpha <= 1.0)) fail("wkgc_alpha", wkgc_alpha, "[0, 1]");
  if (!(transport_coefficient >= 0.0 && transport_coefficient <= 1.0))
    fail("transport_coefficient", transport_coefficient, "[0, 1]");
  if (transport_velocity && free_surface)
    throw InputError("fluid_sph: transport_velocity = true needs free_surface = false (eq. 24 is "
                     "for internal flows)");
  if (!(u_ref >= 0.0)) fail("u_ref", u_ref, ">= 0");
  if (!(advection_cfl > 0.0 && advection_cfl <= 1.0))
    fail("advection_cfl", advection_cfl, "(0, 1]");
  if (!(acoustic_cfl > 0.0 && acoustic_cfl <= 1.0)) fail("acoustic_cfl", acoustic_cfl, "(0, 1]");
  if (!(viscous_number >= 0.0 && viscous_number <= 0.5))
    fail("viscous_number", viscous_number, "[0, 0.5]");
  if (!(fixed_dt >= 0.0)) fail("fixed_dt", fixed_dt, ">= 0");
  if (!(damping_time >= 0.0)) fail("damping_time", damping_time, ">= 0");
  if (!(rho_min_factor > 0.0 && rho_min_factor < 1.0))
    fail("rho_min_factor", rho_min_factor, "(0, 1)");
  if (!(rho_max_factor > 1.0)) fail("rho_max_factor", rho_max_factor, "> 1");
  const VecD<D> size = domain_max - domain_min;
  const std::string axis[] = {"x", "y", "z"};
  for (int c = 0; c < D; ++c)
    if (!(size[c] > 0.0))
      fail("domain_max." + axis[c] + " - domain_min." + axis[c], size[c], "> 0");
  if (D == 3 && inflow.on()) throw InputError("fluid_sph: the inflow buffer is 2-D only");
  if (inflow.on()) {
    if (!periodic_x)
      throw InputError("fluid_sph: inflow.buffer > 0 needs periodic_x (the channel wraps in x)");
    if (!(inflow.buffer <= 0.5 * size[0]))
      fail("inflow.buffer", inflow.buffer, "(0, half the periodic length]");
    if (!(inflow.velocity > 0.0)) fail("inflow.velocity", inflow.velocity, "> 0");
    if (!(inflow.ramp_time >= 0.0)) fail("inflow.ramp_time", inflow.ramp_time, ">= 0");
    if (!(inflow.y_max > inflow.y_min))
      fail("inflow.y_max - inflow.y_min", inflow.y_max - inflow.y_min, "> 0");
  }
  const double cut = 2.0 * h();
  for (int c = 0; c < D; ++c)
    if (periodic()[static_cast<std::size_t>(c)] && size[c] < 3.0 * cut)
      fail("periodic length " + axis[c], size[c], ">= 3 kernel supports (6 h)");
}

template struct BasicSphOptions<2>;
template struct BasicSphOptions<3>;

} // namespace fsi::sph
