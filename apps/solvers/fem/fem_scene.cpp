// The FE structure's scene keys, each declared once where it is read.
#include "fem/fem_spec.hpp"

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
  st.youngs_modulus = mat.real("youngs_modulus", Range::positive(), "E, Pa");
  st.poisson_ratio = mat.real("poisson_ratio", Range::open(-1.0, 0.5), "nu");
  st.density = mat.real("density", Range::positive(), "rho_s, kg/m^3");
  st.plane = mat.choice("plane", {"strain", "stress"}, "strain", "2D idealisation");
  st.material_model =
      mat.choice("model", {"saint_venant_kirchhoff", "neo_hookean"}, "saint_venant_kirchhoff",
                 "strain energy: the paper's St. Venant-Kirchhoff (eq. 35), or compressible "
                 "neo-Hookean (plane strain only), which cannot be crushed flat by a finite "
                 "load (docs/structure_fem.md)");
  if (st.material_model == "neo_hookean" && st.plane != "strain")
    mat.fail("model", "neo_hookean is implemented in plane strain only (plane: strain)");
  mat.finish();
  st.clamped = s.names("clamped", {}, "boundary tags whose nodes are fixed");
  st.clamped_motion =
      s.text("clamped_motion", "",
             "name of a wall with a motion: the clamped nodes follow its rigid motion (u, v, a "
             "prescribed; e.g. a beam clamped to a rolling tank), starting from static "
             "equilibrium with the wall at t = 0; empty: they stay fixed");
  st.interface = s.names("interface", {}, "boundary tags wetted by the fluid");
  if (auto nb = s.block("newmark", "Newmark-beta coefficients (eqs. 40-41)")) {
    st.newmark_beta = nb->real("beta", 0.3025, Range::left_open(0.0, 0.5), "beta_NB");
    st.newmark_gamma = nb->real("gamma", 0.6, Range::closed(0.5, 1.0), "gamma_NB");
    if (!s.context().documenting() &&
        st.newmark_beta < 0.25 * std::pow(st.newmark_gamma + 0.5, 2) - 1e-12)
      nb->fail("beta", "must be >= (gamma + 1/2)^2 / 4 for unconditional stability");
    nb->finish();
  }
  if (auto nr = s.block("newton", "Newton-Raphson controls")) {
    st.newton_tolerance = nr->real("tolerance", 1e-8, Range::open(0.0, 1.0),
                                   "residual norm relative to the load norm");
    st.increment_tolerance = nr->real("increment_tolerance", 1e-10, Range::open(0.0, 1.0),
                                      "increment norm relative to the displacement norm");
    st.newton_max_iterations = nr->integer("max_iterations", 20, Range::closed(1, 1000),
                                           "iterations before the run stops");
    st.newton_substep_levels = nr->integer(
        "substep_levels", 0, Range::closed(0, 10),
        "a step whose Newton fails (no convergence, or an inverted element) is retried as 2, 4, "
        "... 2^levels sub-steps with the loads linear in time, each to the same tolerances; "
        "counted in run.json (docs/structure_fem.md); 0: the run stops");
    nr->finish();
  }
  st.linear_solver = s.choice("linear_solver", {"cholmod", "umfpack", "ldlt", "cg"}, "cholmod",
                              "sparse direct (CHOLMOD, UMFPACK, Eigen LDLT) or preconditioned CG");
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
