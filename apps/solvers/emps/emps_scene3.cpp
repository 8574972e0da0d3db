// The EMPS fluid's keys in a 3-D scene (dimension: 3): the options of 2-D, a tank of triangles
// (a box, or an STL surface), the fluid and the domain as boxes. What 3-D does not have yet is
// refused by name.
#include "emps/emps_spec.hpp"
#include "fsi_app/wall_motion.hpp"
#include "structure_fem/gmsh_reader.hpp"

namespace fsi::app::emps_plugin {

namespace {

// The 2-D keys and options that have no 3-D form yet (docs/fluid_emps.md, "3-D").
void refuse_2d_only(Section& s, const emps::FluidOptions3& o) {
  if (o.wall.contact.model == emps::WallContact::viscous)
    s.fail("wall_contact", "'viscous' is not available in 3-D yet");
  if (o.wall.mirror.pressure == emps::WallPressure::neighbours)
    s.fail("wall_pressure", "'neighbours' is not available in 3-D yet");
}

/// A tank surface from a file: a Gmsh surface mesh (.msh, gmsh -2) or an STL file, both checked
/// as geometry_erp's assemble_surface (InputError `FILE[:LINE]: what`).
erp::StlSurface read_surface_file(const std::filesystem::path& path) {
  if (path.extension() != ".msh") return erp::read_stl_file(path.string());
  const fem::SurfaceMesh mesh = fem::read_gmsh_surface(path.string());
  std::vector<erp::SurfaceFacet> facets;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    erp::SurfaceFacet& f = facets.emplace_back();
    f.n = Vec3::Zero(); // no stored normal: the corner order orients the triangle
    for (std::size_t k = 0; k < 3; ++k)
      f.v[k] = mesh.X[static_cast<std::size_t>(mesh.triangles[t][k])];
    f.where = mesh.where[t];
  }
  return erp::assemble_surface(facets, path.string());
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
  if (auto m =
          s.block("tank_motion",
                  "(dimension 3; optional) the tank's prescribed rigid motion, the 3-D form "
                  "of walls[].motion (docs/fluid_emps.md, \"Moving tanks\"); absent: static")) {
    f.tank_motion_line = m->line();
    f.tank_motion = read_motion3(*m);
  }
  if (!doc && !s.has("tank_file")) return;
  const std::filesystem::path path =
      s.file("tank_file",
             "(dimension 3; optional, instead of tank) the tank's walls as an STL surface (ASCII "
             "or binary) or a Gmsh surface mesh (.msh 4.1 or 2.2 of 3-node triangles, gmsh -2), "
             "each facet's normal (its corners counter-clockwise) pointing into the fluid; "
             "checked as geometry_erp's read_stl (docs/geometry_erp.md)");
  if (doc) return;
  f.tank_line = s.line();
  f.tank_path = path.string();
  f.tank_surface = read_surface_file(path); // InputError `FILE: what is wrong`
}

void read_region_file(Section& s, FluidSpec3& f) {
  const bool doc = s.context().documenting();
  if (!doc && !s.has("region_file")) return;
  const std::filesystem::path path =
      s.file("region_file",
             "(dimension 3; optional, besides or instead of regions) a fluid region as a closed "
             "surface, STL or Gmsh (.msh) as tank_file, of either orientation, filled with the "
             "lattice lo + (i + 1/2, j + 1/2, k + 1/2) l0 from its bounding box's corner lo "
             "(erp::fill_closed_surface); a point inside a box region is left out");
  if (doc) return;
  f.region_line = s.line();
  f.region_path = path.string();
  f.region_surface = read_surface_file(path); // InputError `FILE: what is wrong`
  if (f.region_surface->open_edges > 0)
    s.fail("region_file", f.region_path + ": " + std::to_string(f.region_surface->open_edges) +
                              " edges with one facet (a fluid region must be a closed surface)");
}

std::shared_ptr<const SolverSpec> read_fluid3(Section& s) {
  auto spec = std::make_shared<FluidSpec3>();
  FluidSpec3& f = *spec;
  OptionReader reader(s);
  emps::visit_options(f.options, reader);
  refuse_2d_only(s, f.options);
  read_tank(s, f);
  read_region_file(s, f);
  read_box_area(s, f.options.l0, f.regions, f.domain, f.region_surface.has_value());
  f.periodic_z = read_periodic_z(s);
  if (f.periodic_z) {
    check_periodic_z(s, f.tank, f.domain, f.options.l0);
    if (f.tank_motion) s.fail("periodic_z", "not available with tank_motion yet");
    f.periodic = periodic_refusal(s, "periodic_z");
    f.periodic_structures = s.message("periodic_z", "not available with structures yet (their "
                                                    "interfaces would not wrap)");
  }
  return spec;
}

} // namespace fsi::app::emps_plugin
