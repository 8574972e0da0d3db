// The EMPS fluid's scene keys, each declared once where it is read.
#include "emps/emps_spec.hpp"

namespace fsi::app::emps_plugin {

std::shared_ptr<const SolverSpec> read_fluid(Section& s) {
  const bool doc = s.context().documenting();
  if (!doc && s.context().dimension == 3) return read_fluid3(s);
  if (doc) {
    FluidSpec3 documented;
    read_tank(s, documented);
    read_region_file(s, documented);
    read_periodic_z(s);
  } else {
    for (const char* key : {"tank", "tank_file", "tank_motion"})
      if (s.has(key))
        s.fail(key, "is a key of 3-D scenes (dimension: 3); in 2-D the tank is a wall polyline");
    if (s.has("region_file"))
      s.fail("region_file", "is a key of 3-D scenes (dimension: 3); in 2-D regions are polygons");
    if (s.has("periodic_z")) s.fail("periodic_z", "is a key of 3-D scenes (dimension: 3)");
  }
  auto spec = std::make_shared<FluidSpec>();
  OptionReader reader(s);
  emps::visit_options(spec->options, reader);
  spec->area = read_particle_area(s, spec->options.l0);
  return spec;
}

} // namespace fsi::app::emps_plugin
