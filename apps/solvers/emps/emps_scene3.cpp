// The EMPS fluid's keys in a 3-D scene (dimension: 3): the options of 2-D, a tank of triangles
// (a box, or an STL surface), the fluid and the domain as boxes. What 3-D does not have yet is
// refused by name.
#include "emps/emps_spec.hpp"

namespace fsi::app::emps_plugin {

namespace {

// The 2-D keys and options that have no 3-D form yet (docs/fluid_emps.md, "3-D").
void refuse_2d_only(Section& s, const emps::FluidOptions3& o) {
  if (s.has("convex_corners")) s.fail("convex_corners", "not available in 3-D yet");
  if (o.wall.contact.model == emps::WallContact::viscous)
    s.fail("wall_contact", "'viscous' is not available in 3-D yet");
  if (o.wall.mirror.pressure == emps::WallPressure::neighbours)
    s.fail("wall_pressure", "'neighbours' is not available in 3-D yet");
}

} // namespace

void read_tank(Section& s, FluidSpec3& f) {
  const bool doc = s.context().documenting();
  if (!doc && s.has("tank") && s.has("tank_file"))
    s.fail("tank_file", "give either tank (a box) or tank_file (a surface), not both");
  if (auto t = s.block("tank", "(dimension 3) a closed box tank of 12 triangles, its "
                               "inside min..max (the fluid's walls; 2-D scenes give wall "
                               "polylines)")) {
    f.tank_line = t->line();
    f.tank = read_box_region(*t, "the tank's inside");
  }
  if (!doc && !s.has("tank_file")) return;
  const std::filesystem::path path =
      s.file("tank_file",
             "(dimension 3; optional, instead of tank) the tank's walls as an STL surface (ASCII "
             "or binary), each facet's normal pointing into the fluid; checked as "
             "geometry_erp's read_stl (docs/geometry_erp.md)");
  if (doc) return;
  f.tank_line = s.line();
  f.tank_path = path.string();
  f.tank_surface = erp::read_stl_file(path.string()); // InputError `FILE: what is wrong`
}

std::shared_ptr<const SolverSpec> read_fluid3(Section& s) {
  auto spec = std::make_shared<FluidSpec3>();
  FluidSpec3& f = *spec;
  OptionReader reader(s);
  emps::visit_options(f.options, reader);
  refuse_2d_only(s, f.options);
  read_tank(s, f);
  read_box_area(s, f.options.l0, f.regions, f.domain);
  return spec;
}

} // namespace fsi::app::emps_plugin
