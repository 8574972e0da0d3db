// The SPH fluid's keys in a 3-D scene (dimension: 3): the options of 2-D, an open box tank, the
// fluid as boxes and the domain as a box. What is 2-D only is refused by name.
#include "sph/sph_spec.hpp"

#include "fsi/core/format.hpp"

#include <cmath>

namespace fsi::app::sph_plugin {

std::optional<Box3> read_tank(Section& s) {
  auto t = s.block(
      "tank", "(dimension 3) an open box tank, y up: its inside min..max (both required), walls "
              "of 4 dummy layers under its floor and behind its four sides, no "
              "lid (the 3-D scene's walls; 2-D scenes give wall polylines)");
  if (!t) return std::nullopt;
  return read_box_region(*t, "the tank's inside");
}

bool read_periodic_z(Section& s) {
  return s.boolean("periodic_z", false,
                   "(dimension 3) the fluid and the tank wrap along z over the tank's depth, a "
                   "whole number of l0: a slab with no walls behind its z faces (quasi-2-D runs); "
                   "needs tank, and a domain (if given) of the tank's z");
}

std::string periodic_refusal(const Section& s, const std::string& key) {
  return s.message(key, "not yet supported under mpirun (issue 47): a periodic fluid cannot be "
                        "decomposed; run it without mpirun");
}

std::shared_ptr<const SolverSpec> read_sph3(Section& s) {
  for (const char* key :
       {"inflow", "interface_layers", "interface_spacing", "interface_acceleration"})
    if (s.has(key)) s.fail(key, "is not yet available in a 3-D scene (dimension: 3)");
  auto spec = std::make_shared<SphSpec3>();
  SphSpec3& f = *spec;
  OptionReader reader(s);
  sph::visit_options(f.options, reader);
  f.tank = read_tank(s);
  read_box_area(s, f.options.dp, f.regions, f.domain);
  f.periodic_z = read_periodic_z(s);
  if (f.periodic_z) f.periodic = periodic_refusal(s, "periodic_z");
  if (f.periodic_z && !s.context().documenting()) {
    if (!f.tank) s.fail("periodic_z", "needs a tank (its depth along z is the period)");
    const double layers = (f.tank->max.z() - f.tank->min.z()) / f.options.dp;
    if (std::abs(layers - std::round(layers)) > 1e-9 * layers)
      s.fail("periodic_z", "the tank's depth " + significant(f.tank->max.z() - f.tank->min.z(), 6) +
                               " m is not a whole number of l0 = " + significant(f.options.dp, 6) +
                               " m (the lattice would not wrap)");
    if (f.domain && (f.domain->min.z() != f.tank->min.z() || f.domain->max.z() != f.tank->max.z()))
      s.fail("domain", "with periodic_z its z range must be the tank's (the period)");
  }
  if (f.options.transport_velocity && f.options.free_surface)
    s.fail("transport_velocity", "needs free_surface: false (eq. 24 is for internal flows)");
  return spec;
}

} // namespace fsi::app::sph_plugin
