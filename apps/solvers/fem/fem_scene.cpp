// The FE structure's scene keys, each declared once where it is read.
#include "fem/fem_spec.hpp"

#include "fsi_app/material_reader.hpp"
#include "structure_fem/options.hpp"

#include <cmath>

namespace fsi::app::fem_plugin {

namespace {

MeshSpec read_mesh(Section s) {
  MeshSpec m;
  const bool doc = s.context().documenting();
  m.kind = s.choice("kind", {"rectangle", "gmsh"}, "",
                    "built-in structured T6 rectangle, or a Gmsh file of 6-node triangles");
  if (doc || m.kind == "rectangle") {
    m.origin = s.vec2("origin", Vec2::Zero(), "lower-left corner, m");
    m.width = s.real("width", Range::positive(), "m");
    m.height = s.real("height", Range::positive(), "m");
    m.elements_x = s.integer("elements_x", Range::closed(1, 10000), "element columns");
    m.elements_y = s.integer("elements_y", Range::closed(1, 10000), "element rows");
    m.diagonals = s.choice("diagonals", {"rising", "mirrored"}, "rising",
                           "how each quad is split: rising, along its lower-left to upper-right "
                           "diagonal; mirrored, the left half's the other way, so both top "
                           "corners belong to two triangles (a plate's free end on top)");
  }
  if (doc || m.kind == "gmsh")
    m.file = s.file(
        "file",
        "Gmsh .msh: format 4.1 (ASCII or binary) or 2.2 (ASCII), second order (gmsh -2 -order 2)");
  s.finish();
  return m;
}

} // namespace

std::shared_ptr<const SolverSpec> read_structure(Section& s) {
  auto spec = std::make_shared<StructureSpec>();
  StructureSpec& st = *spec;
  st.mesh = read_mesh(s.required_block("mesh", "the T6 mesh"));
  auto mat = s.required_block("material", "hyperelastic material (eq. 35 by default)");
  read_material(mat, st.options.material);
  st.clamped = s.names("clamped", {}, "boundary tags whose nodes are fixed");
  st.clamped_motion =
      s.text("clamped_motion", "",
             "name of a wall with a motion: the clamped nodes follow its rigid motion (u, v, a "
             "prescribed; e.g. a beam clamped to a rolling tank), starting from static "
             "equilibrium with the wall at t = 0; empty: they stay fixed");
  st.interface = s.names("interface", {}, "boundary tags wetted by the fluid");
  if (auto nb = s.block("newmark", "Newmark-beta coefficients (eqs. 40-41)")) {
    OptionReader reader(*nb);
    fem::NewmarkOptions& n = st.options.newmark;
    fem::visit_options(n, reader);
    if (!s.context().documenting() && n.beta < 0.25 * std::pow(n.gamma + 0.5, 2) - 1e-12)
      nb->fail("beta", "must be >= (gamma + 1/2)^2 / 4 for unconditional stability");
    nb->finish();
  }
  if (auto nr = s.block("newton", "Newton-Raphson controls")) {
    OptionReader reader(*nr);
    fem::visit_options(st.options.newton, reader);
    nr->finish();
  }
  OptionReader reader(s);
  fem::visit_options(st.options.linear_solver, reader);
  for (auto& load : s.list("loads", "constant nodal forces (structure-only scenes)")) {
    PointLoadSpec p;
    p.boundary = load.text("boundary", "boundary tag the force is spread over");
    p.force = load.vec2("force", "total force per unit thickness, N/m, applied as a uniform "
                                 "traction over the tagged edges (consistent nodal loads)");
    load.finish();
    st.loads.push_back(p);
  }
  return spec;
}

} // namespace fsi::app::fem_plugin
