// The FE structure's scene keys, each declared once where it is read.
#include "fem/fem_spec.hpp"

#include "fsi_app/material_reader.hpp"
#include "fsi_app/wall_motion.hpp"
#include "structure_fem/options.hpp"

#include <cmath>

namespace fsi::app::fem_plugin {

namespace {

MeshSpec read_mesh(Section s) {
  MeshSpec m;
  const bool doc = s.context().documenting();
  const bool three_d = s.context().dimension == 3;
  m.kind = s.choice("kind", {"rectangle", "box", "gmsh"}, "",
                    "built-in structured T6 rectangle (2-D; sides left, right, bottom, top) or "
                    "T10 box (3-D; sides left, right at x min, max, bottom, top at y min, max, "
                    "back, front at z min, max), or a Gmsh file of 6-node triangles (2-D) or "
                    "10-node tetrahedra (3-D; tags: its physical surfaces)");
  if (!doc && (m.kind == "box") != three_d && m.kind != "gmsh")
    s.fail("kind", three_d ? "a 3-D scene's mesh is a box or gmsh (rectangle is 2-D)"
                           : "box is a 3-D mesh (give dimension: 3, or a rectangle)");
  if (doc || m.kind != "gmsh") {
    const std::string origin_doc = "lower-left corner, m (box: [x, y, z], the smallest corner)";
    if (three_d && !doc)
      m.origin3 = s.vec3("origin", Vec3::Zero(), origin_doc);
    else
      m.origin = s.vec2("origin", Vec2::Zero(), origin_doc);
    m.width = s.real("width", Range::positive(), "along x, m");
    m.height = s.real("height", Range::positive(), "along y, m");
    if (doc || three_d) m.depth = s.real("depth", Range::positive(), "box: along z, m");
    m.elements_x = s.integer("elements_x", Range::closed(1, 10000), "element columns (along x)");
    m.elements_y = s.integer("elements_y", Range::closed(1, 10000), "element rows (along y)");
    if (doc || three_d)
      m.elements_z = s.integer("elements_z", Range::closed(1, 10000),
                               "box: element layers along z (a box cell is 6 T10)");
  }
  if (doc || m.kind == "rectangle")
    m.diagonals = s.choice("diagonals", {"rising", "mirrored"}, "rising",
                           "how each quad is split: rising, along its lower-left to upper-right "
                           "diagonal; mirrored, the left half's the other way, so both top "
                           "corners belong to two triangles (a plate's free end on top)");
  if (doc || m.kind == "gmsh")
    m.file = s.file("file", "Gmsh .msh: format 4.1 (ASCII or binary) or 2.2 (ASCII), second "
                            "order (gmsh -2 -order 2; 3-D: gmsh -3 -order 2)");
  s.finish();
  return m;
}

PointLoadSpec read_load(Section& load) {
  PointLoadSpec p;
  const bool doc = load.context().documenting();
  const bool three_d = load.context().dimension == 3;
  p.boundary = load.text("boundary", "boundary tag the force is spread over");
  const std::string force_doc = "total force per unit thickness, N/m, applied as a uniform "
                                "traction over the tagged edges (consistent nodal loads); 3-D: "
                                "[x, y, z], N, over the tagged faces";
  if (three_d && !doc) {
    p.force3 = load.vec3("force", Vec3::Zero(), force_doc);
    p.pressure = load.real("pressure", 0.0, Range::any(), "3-D: pressure on the tagged faces, Pa");
    if (!load.has("force") && !load.has("pressure")) load.fail("", "give force, pressure or both");
  } else {
    p.force = load.vec2("force", force_doc);
    if (doc) load.real("pressure", 0.0, Range::any(), "3-D: pressure on the tagged faces, Pa");
  }
  load.finish();
  return p;
}

} // namespace

std::shared_ptr<const SolverSpec> read_structure(Section& s) {
  auto spec = std::make_shared<StructureSpec>();
  StructureSpec& st = *spec;
  st.mesh = read_mesh(s.required_block("mesh", "the T6 mesh (3-D: T10)"));
  auto mat = s.required_block("material", "hyperelastic material (eq. 35 by default)");
  read_material(mat, st.options.material);
  st.clamped = s.names("clamped", {}, "boundary tags whose nodes are fixed");
  const bool three_d = s.context().dimension == 3, doc = s.context().documenting();
  if (three_d || doc)
    st.sliding = s.names("sliding", {},
                         "3-D: boundary tags whose faces slide in their plane, which must be a "
                         "plane x, y or z = const: the displacement along that axis is held "
                         "(symmetry planes, the sides of a slab)");
  st.clamped_motion =
      s.text("clamped_motion", "",
             "name of a wall with a motion: the clamped nodes follow its rigid motion (u, v, a "
             "prescribed; e.g. a beam clamped to a rolling tank), starting from static "
             "equilibrium with the wall at t = 0; empty: they stay fixed");
  if (three_d || doc) {
    if (auto r = s.block("clamped_rigid_motion",
                         "3-D: the clamped faces' rigid motion, the keys of fluid.tank_motion "
                         "(a translation along x, y or z, or a rotation about an axis; a "
                         "sinusoid or a table), starting from static equilibrium with the clamp "
                         "at t = 0")) {
      st.clamped_rigid_motion_line = r->line();
      st.clamped_rigid_motion = read_motion3(*r);
    }
    if (!doc && st.clamped_rigid_motion && st.clamped.empty())
      s.fail("clamped_rigid_motion", "needs clamped boundary tags to move");
    if (!doc && three_d && !st.clamped_motion.empty())
      s.fail("clamped_motion", "names a 2-D wall; 3-D scenes have none: move the clamp with "
                               "clamped_rigid_motion");
  }
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
  if (s.context().dimension == 3) // the 3-D default (fem::BasicStructureOptions<T10>)
    st.options.linear_solver.kind = fem::LinearSolverKind::cholmod;
  OptionReader reader(s);
  fem::visit_options(st.options.linear_solver, reader);
  for (auto& load : s.list("loads", "constant nodal forces (structure-only scenes)"))
    st.loads.push_back(read_load(load));
  return spec;
}

} // namespace fsi::app::fem_plugin
