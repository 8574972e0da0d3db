// The SPH fluid's scene keys, each declared once where it is read.
#include "sph/sph_spec.hpp"

#include "fsi_app/solver_plugin.hpp"

#include <set>

namespace fsi::app::sph_plugin {

namespace {

// A key of another fluid type (e.g. emps' alpha_rep) given to sph: name it and its type.
void refuse_foreign_keys(Section& s) {
  const std::set<std::string> own = declared_keys(find_fluid_plugin("sph")->read);
  for (const FluidPlugin& p : fluid_plugins()) {
    if (p.name == "sph") continue;
    for (const std::string& key : declared_keys(p.read))
      if (!own.count(key) && s.has(key))
        s.fail(key, "is a key of fluid type " + p.name + ", not of sph (remove it, or move it " +
                        "into a block " + s.path() + "." + p.name + ": to keep it for that type)");
  }
}

} // namespace

std::shared_ptr<const SolverSpec> read_sph(Section& s) {
  const bool doc = s.context().documenting();
  if (!doc) refuse_foreign_keys(s);
  if (!doc && s.context().dimension == 3) return read_sph3(s);
  if (doc) {
    read_tank(s);
    read_periodic_z(s);
  } else {
    if (s.has("tank"))
      s.fail("tank", "is a key of 3-D scenes (dimension: 3); in 2-D the tank is a wall polyline");
    if (s.has("periodic_z")) s.fail("periodic_z", "is a key of 3-D scenes (dimension: 3)");
  }
  auto spec = std::make_shared<SphSpec>();
  SphSpec& f = *spec;
  OptionReader reader(s);
  sph::visit_options(f.options, reader);
  f.interface_layers =
      s.integer("interface_layers", 4, Range::closed(1.0, 8.0),
                "boundary points fill a coupled structure within "
                "interface_layers l0 of its interface (lattice at interface_spacing)");
  f.interface_spacing =
      s.real("interface_spacing", 1.0, Range::left_open(0.0, 1.0),
             "the boundary points' lattice spacing in l0, each of volume spacing^2 (0.5 with a "
             "TL-SPH solid at dp_S = l0/2: the solid's own lattice; unused where the solid "
             "hands over its particles, tlsph.interface_particles)");
  f.interface_acceleration = s.boolean(
      "interface_acceleration", false,
      "a coupled interface's mean acceleration over the coupling step in the wall's dummy "
      "pressure (eqs. 16-17); false: zero (explicit coupling with a light structure feeds it "
      "back unstably)");
  if (auto in = s.block("inflow", "channel inflow buffer (eqs. 25-26): the domain wraps in x and "
                                  "the particles in [domain.min.x, + buffer) get the parabola")) {
    sph::Inflow& inflow = f.options.inflow;
    inflow.buffer = in->real("buffer", Range::positive(), "buffer length, m (reference: 20 l0)");
    inflow.velocity = in->real("velocity", Range::positive(), "U0, mean over the height, m/s");
    inflow.ramp_time = in->real("ramp_time", 0.0, Range::non_negative(), "t_s of eq. 26, s");
    inflow.y_min = in->real("y_min", Range::any(), "lower channel wall, m");
    inflow.y_max = in->real("y_max", Range::any(), "upper channel wall, m");
    in->finish();
    f.periodic = periodic_refusal(s, "inflow");
  }
  f.area = read_particle_area(s, f.options.dp);
  if (!doc) {
    if (f.options.inflow.on() && !f.area.domain)
      s.fail("inflow", "needs a domain (its x extent is the period)");
    if (f.options.transport_velocity && f.options.free_surface)
      s.fail("transport_velocity", "needs free_surface: false (eq. 24 is for internal flows)");
  }
  return spec;
}

} // namespace fsi::app::sph_plugin
