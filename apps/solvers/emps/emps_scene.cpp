// The EMPS fluid's scene keys, each declared once where it is read.
#include "emps/emps_spec.hpp"

namespace fsi::app::emps_plugin {

std::shared_ptr<const SolverSpec> read_fluid(Section& s) {
  if (!s.context().documenting() && s.context().dimension == 3)
    s.fail("type", "emps is not yet available in 3-D (dimension: 3 takes fluid type sph)");
  auto spec = std::make_shared<FluidSpec>();
  OptionReader reader(s);
  emps::visit_options(spec->options, reader);
  spec->area = read_particle_area(s, spec->options.l0);
  return spec;
}

} // namespace fsi::app::emps_plugin
