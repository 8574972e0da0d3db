// The SPH fluid's scene keys, each declared once where it is read.
#include "sph/sph_spec.hpp"

#include "fsi_app/solver_plugin.hpp"

#include <set>

namespace fsi::app::sph_plugin {

namespace {

// The top-level keys a fluid plug-in declares (its read in documentation mode).
std::set<std::string> declared_keys(const FluidPlugin& plugin) {
  ReadContext ctx;
  ctx.collector = std::make_unique<std::vector<KeyDoc>>();
  Section doc(YAML::Node(), "", ctx);
  plugin.read(doc);
  std::set<std::string> keys;
  for (const KeyDoc& k : *ctx.collector) keys.insert(k.path.substr(0, k.path.find_first_of(".[")));
  return keys;
}

// A key of another fluid type (e.g. emps' alpha_rep) given to sph: name it and its type.
void refuse_foreign_keys(Section& s) {
  const std::set<std::string> own = declared_keys(*find_fluid_plugin("sph"));
  for (const FluidPlugin& p : fluid_plugins()) {
    if (p.name == "sph") continue;
    for (const std::string& key : declared_keys(p))
      if (!own.count(key) && s.has(key))
        s.fail(key, "is a key of fluid type " + p.name + ", not of sph (remove it to run sph)");
  }
}

} // namespace

std::shared_ptr<const SolverSpec> read_sph(Section& s) {
  const bool doc = s.context().documenting();
  if (!doc) refuse_foreign_keys(s);
  auto spec = std::make_shared<SphSpec>();
  SphSpec& f = *spec;
  f.density = s.real("density", Range::positive(), "rho, kg/m^3");
  f.viscosity = s.real("viscosity", 0.0, Range::non_negative(),
                       "kinematic viscosity nu, m^2/s; 0 skips the viscous loop");
  f.l0 = s.real("l0", Range::positive(), "initial particle spacing, m (sph: dp)");
  f.sound_speed = s.real("sound_speed", Range::positive(),
                         "artificial sound speed, m/s (sph: c0 of p = c0^2 (rho - rho0), eq. 2)");
  f.h_over_dp = s.real("h_over_dp", 1.3, Range::closed(1.0, 2.0),
                       "smoothing length h / dp (Wendland C2, support 2h)");
  f.correction = s.choice("correction", {"none", "rkgc"}, "rkgc",
                          "none: standard Riemann-SPH; rkgc: reverse kernel gradient correction on "
                          "the central pressure term (eqs. 18-20)");
  f.wkgc_alpha = s.real("wkgc_alpha", 0.3, Range::closed(0.0, 1.0),
                        "alpha of the WKGC weighting (eqs. 21-22); 0: B unweighted");
  f.free_surface = s.boolean("free_surface", true,
                             "true: rho = max(rho_sum, rho0) at re-initialisation (free-surface "
                             "flows); false: rho = rho_sum (internal flows)");
  f.transport_velocity =
      s.boolean("transport_velocity", false,
                "transport-velocity shift once per advection step (eqs. 23-24; internal flows, "
                "needs free_surface: false)");
  f.u_ref = s.real("u_ref", 0.0, Range::non_negative(),
                   "reference speed of the advection criterion, m/s (0: sound_speed / 10)");
  f.advection_cfl = s.real("advection_cfl", 0.25, Range::left_open(0.0, 1.0),
                           "advection step Dt = advection_cfl h / max(|v|, sqrt(4 h |a|), u_ref, "
                           "nu / h)");
  f.acoustic_cfl = s.real("acoustic_cfl", 0.6, Range::left_open(0.0, 1.0),
                          "acoustic step dt = acoustic_cfl h / max(c0 + |v|, sqrt(4 h |a|)) "
                          "(sph steps by its own criteria: time.courant is not used)");
  f.interface_layers = s.integer("interface_layers", 4, Range::closed(1.0, 8.0),
                                 "boundary points fill a coupled structure within "
                                 "interface_layers l0 of its interface (lattice at l0)");
  f.interface_acceleration = s.boolean(
      "interface_acceleration", false,
      "a coupled interface's mean acceleration over the coupling step in the wall's dummy "
      "pressure (eqs. 16-17); false: zero (explicit coupling with a light structure feeds it "
      "back unstably)");
  f.damping_time =
      s.real("damping_time", 0.0, Range::non_negative(),
             "initial damping phase T_d: velocities damped at a rate 20/T_d (1 - t/T_d) "
             "(quiet hydrostatic starts), s");
  f.riemann_limiter = s.boolean("riemann_limiter", true,
                                "eq. 5's low-dissipation limiter beta = min(3 max(u/c0, 0), 1); "
                                "false: beta = 1 (settling flows, docs/fluid_sph.md)");
  if (auto in = s.block("inflow", "channel inflow buffer (eqs. 25-26): the domain wraps in x and "
                                  "the particles in [domain.min.x, + buffer) get the parabola")) {
    f.inflow.buffer = in->real("buffer", Range::positive(), "buffer length, m (reference: 20 l0)");
    f.inflow.velocity = in->real("velocity", Range::positive(), "U0, mean over the height, m/s");
    f.inflow.ramp_time = in->real("ramp_time", 0.0, Range::non_negative(), "t_s of eq. 26, s");
    f.inflow.y_min = in->real("y_min", Range::any(), "lower channel wall, m");
    f.inflow.y_max = in->real("y_max", Range::any(), "upper channel wall, m");
    in->finish();
  }
  f.area = read_particle_area(s, f.l0);
  if (!doc) {
    if (f.inflow.on() && !f.area.domain)
      s.fail("inflow", "needs a domain (its x extent is the period)");
    if (f.transport_velocity && f.free_surface)
      s.fail("transport_velocity", "needs free_surface: false (eq. 24 is for internal flows)");
  }
  return spec;
}

} // namespace fsi::app::sph_plugin
