// The SPH fluid's keys in a 3-D scene (dimension: 3): the options of 2-D, an open box tank, the
// fluid as boxes and the domain as a box. What is 2-D only is refused by name.
#include "sph/sph_spec.hpp"

namespace fsi::app::sph_plugin {

std::optional<Box3> read_tank(Section& s) {
  auto t = s.block(
      "tank", "(dimension 3) an open box tank, y up: its inside min..max (both required), walls "
              "of 4 dummy layers under its floor and behind its four sides, no "
              "lid (the 3-D scene's walls; 2-D scenes give wall polylines)");
  if (!t) return std::nullopt;
  return read_box_region(*t, "the tank's inside");
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
  if (f.periodic_z && !s.context().documenting())
    check_periodic_z(s, f.tank, f.domain, f.options.dp);
  if (f.options.transport_velocity && f.options.free_surface)
    s.fail("transport_velocity", "needs free_surface: false (eq. 24 is for internal flows)");
  return spec;
}

} // namespace fsi::app::sph_plugin
