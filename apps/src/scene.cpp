#include "fsi_app/scene.hpp"

#include "fsi/core/error.hpp"
#include "fsi_app/output/interface_history.hpp"
#include "fsi_app/overrides.hpp"
#include "fsi_app/resources.hpp"
#include "fsi_app/scene_reader.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>
#include <yaml-cpp/depthguard.h>

namespace fsi::app {

namespace {

// Every scene key is declared in the functions below, once.

TimeSpec read_time(Section s) {
  TimeSpec t;
  t.end = s.real("end", Range::positive(), "simulated end time, s");
  t.dt = s.optional_real("dt", Range::positive(), "fixed time step, s (give dt or courant)");
  t.courant = s.optional_real("courant", Range::left_open(0.0, 1.0),
                              "adaptive step from this Courant number on c and the fastest "
                              "particle, with the viscous limit (fluid scenes)");
  if (!s.context().documenting()) {
    if (t.dt && t.courant) s.fail("courant", "give either dt or courant, not both");
    if (!t.dt && !t.courant) s.fail("", "one of dt or courant is required");
    if (t.dt && *t.dt > t.end) s.fail("dt", "is larger than time.end");
  }
  s.finish();
  return t;
}

const std::vector<std::string> kFieldNames = {"velocity",     "pressure",     "pnd",
                                              "free_surface", "displacement", "von_mises"};
const std::vector<std::string> kProbeQuantities = {
    "displacement_x", "displacement_y", "displacement_x_tank", "displacement_y_tank",
    "surge_front",    "pressure",       "mean_pressure",       "mean_speed",
    "kinetic_energy", "wall_force_x",   "wall_force_y"};
const std::vector<std::string> kForceParts = {"total", "pressure", "repulsive", "viscous"};

ProbeSpec read_probe(Section s) {
  ProbeSpec p;
  p.line = s.line();
  p.name = s.text("name", "column name in probes.csv (letters, digits, _)");
  p.quantity = s.choice("quantity", kProbeQuantities, "",
                        "what is sampled: a node's displacement; a node's displacement in the "
                        "frame of the wall its structure is clamped to (clamped_motion: the "
                        "rigid motion undone, x and y along the tank's axes); the surge front "
                        "(largest x of particles with pnd >= n0/2, i.e. not spray); the pressure "
                        "at a point (MPS-weighted mean within r_e); mean_pressure, the plain mean "
                        "over the particles inside the box min..max; mean_speed and "
                        "kinetic_energy (J per m of depth) of all particles; wall_force_x|y, "
                        "the fluid's force on the coupled structure (on all walls without one), "
                        "N/m, of the last step");
  p.structure = s.text("structure", "", "structure name, for displacement probes");
  p.node = s.optional_integer("node", Range::non_negative(), "FE node index (or give point)");
  p.point = s.optional_vec2("point", "reference position of the FE node, or the fluid point, m");
  p.box_min = s.optional_vec2("min", "mean_pressure: lower-left corner of the box, m");
  p.box_max = s.optional_vec2("max", "mean_pressure: upper-right corner of the box, m");
  p.part = s.choice("part", kForceParts, "total",
                    "wall_force: the wall term carried: pressure (mirror, eqs. 25-26), repulsive "
                    "(eq. 27 and wall damping), viscous (eq. 24) or their total");
  if (!s.context().documenting()) {
    const bool ok_name = !p.name.empty() && std::all_of(p.name.begin(), p.name.end(), [](char c) {
      return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
    });
    if (!ok_name) s.fail("name", "'" + p.name + "' is not a valid column name");
    const bool on_structure = p.quantity.rfind("displacement", 0) == 0;
    if (on_structure && p.structure.empty()) s.fail("structure", "required key missing");
    if (on_structure && !p.node && !p.point) s.fail("", "give node or point");
    if (p.quantity == "pressure" && !p.point) s.fail("point", "required key missing");
    if (p.quantity == "mean_pressure") {
      if (!p.box_min) s.fail("min", "required key missing");
      if (!p.box_max) s.fail("max", "required key missing");
      if (p.box_max->x() <= p.box_min->x() || p.box_max->y() <= p.box_min->y())
        s.fail("max", "must lie above and right of min");
    }
  }
  s.finish();
  return p;
}

OutputSpec read_output(Section s, double end_time, std::vector<Section>& probe_sections) {
  OutputSpec o;
  o.interval = s.real("interval", Range::positive(), "simulated time between frames, s");
  o.fields = s.names("fields", kFieldNames,
                     "fields written to fields.h5 (particle positions and mesh geometry always)");
  for (const auto& f : o.fields)
    if (std::find(kFieldNames.begin(), kFieldNames.end(), f) == kFieldNames.end())
      s.fail("fields", "unknown field '" + f +
                           "' (known: velocity, pressure, pnd, free_surface, "
                           "displacement, von_mises)");
  std::set<std::string> names;
  probe_sections = s.list("probes", "sampled every frame into probes.csv");
  for (auto& probe : probe_sections) {
    o.probes.push_back(read_probe(probe));
    if (!s.context().documenting() && !names.insert(o.probes.back().name).second)
      probe.fail("name", "duplicate probe name '" + o.probes.back().name + "'");
  }
  if (!s.context().documenting() && o.interval > end_time)
    s.fail("interval", "is larger than time.end");
  s.finish();
  return o;
}

MotionSpec read_motion(Section s) {
  MotionSpec m;
  const bool doc = s.context().documenting();
  m.kind = s.choice("kind", {"sinusoid", "table"}, "",
                    "sinusoid: amplitude sin(2 pi t / period + phase); table: CSV time,value");
  m.dof = s.choice("dof", {"rotation", "x", "y"}, "rotation",
                   "rotation about pivot, or translation along x or y");
  m.pivot = s.vec2("pivot", Vec2::Zero(), "rotation centre in the scene frame, m");
  if (doc || m.kind == "sinusoid") {
    m.amplitude = s.real("amplitude", Range::any(), "rad for rotation, m for translation");
    m.period = s.real("period", Range::positive(), "s");
    m.phase = s.real("phase", 0.0, Range::any(), "rad");
  }
  if (doc || m.kind == "table") {
    m.table = s.file("table", "CSV with header; columns time (s) and value");
    const std::string unit = s.choice("unit", {"deg", "rad", "m"}, "rad", "unit of the values");
    const double scale =
        s.real("scale", 1.0, Range::any(),
               "factor on the values, e.g. -1 for a table whose positive angles turn clockwise "
               "(the scene's turn counter-clockwise)");
    m.table_scale = scale * (unit == "deg" ? M_PI / 180.0 : 1.0);
    if (!doc && (unit == "m") != (m.dof != "rotation"))
      s.fail("unit", "'" + unit + "' does not match dof '" + m.dof + "'");
  }
  s.finish();
  return m;
}

WallSpec read_wall(Section s) {
  WallSpec w;
  w.line = s.line();
  w.name = s.text("name", "wall name, for messages");
  w.polyline =
      s.points("polyline", 2, "vertices; the fluid lies on the left of each directed segment");
  w.closed = s.boolean("closed", false, "join the last vertex to the first");
  if (auto m = s.block("motion", "prescribed rigid motion; absent: the wall is static"))
    w.motion = read_motion(*m);
  if (!s.context().documenting())
    for (std::size_t i = 0; i + 1 < w.polyline.size(); ++i)
      if ((w.polyline[i + 1] - w.polyline[i]).norm() == 0.0)
        s.fail("polyline", "points " + std::to_string(i) + " and " + std::to_string(i + 1) +
                               " coincide (zero-length segment)");
  s.finish();
  return w;
}

std::vector<Vec2> read_region(Section s) {
  const bool doc = s.context().documenting();
  std::vector<Vec2> polygon;
  if (doc || s.has("polygon")) polygon = s.points("polygon", 3, "closed polygon to fill, m");
  if (doc || !s.has("polygon")) {
    const Vec2 lo = s.vec2("min", "lower-left corner of a rectangle to fill, m");
    const Vec2 hi = s.vec2("max", "upper-right corner, m");
    if (!doc && (hi.x() <= lo.x() || hi.y() <= lo.y()))
      s.fail("max", "must lie above and right of min");
    if (!doc) polygon = {lo, {hi.x(), lo.y()}, hi, {lo.x(), hi.y()}};
  }
  s.finish();
  return polygon;
}

FluidSpec read_fluid(Section s) {
  FluidSpec f;
  f.line = s.line();
  const bool doc = s.context().documenting();
  f.density = s.real("density", Range::positive(), "rho, kg/m^3");
  f.viscosity = s.real("viscosity", 0.0, Range::non_negative(),
                       "kinematic viscosity nu, m^2/s; 0 skips the viscous loop");
  f.l0 = s.real("l0", Range::positive(), "initial particle spacing, m");
  f.re_over_l0 = s.real("re_over_l0", 3.1, Range::closed(2.0, 5.0), "effective radius r_e / l0");
  f.sound_speed = s.real("sound_speed", Range::positive(), "c of eq. 15, m/s");
  f.beta = s.real("beta", 1.0, Range::left_open(0.0, 1.5), "free-surface threshold, eq. 17");
  f.alpha_rep =
      s.real("alpha_rep", 0.0, Range::non_negative(), "repulsive coefficient of eq. 27, N/m^3");
  f.wall_condition =
      s.choice("wall_condition", {"no_slip", "slip"}, "no_slip", "viscous wall condition (eq. 24)");
  f.artificial_viscosity = s.real(
      "artificial_viscosity", 0.0, Range::non_negative(),
      "alpha: closing particle pairs feel a viscosity alpha c l0 along their line of centres "
      "(damps acoustic noise; not in the paper, 0 = off)");
  f.wall_contact = s.choice(
      "wall_contact", {"paper", "damped", "viscous"}, "paper",
      "particle-wall contact: paper, the repulsive term of eq. 27 alone; damped, eq. 27 plus a "
      "damper on the wall-normal approach velocity within l0 of a wall (rate wall_damping c/l0 "
      "(1 - r/l0), a wall force); viscous, eq. 27 plus the closing-pair viscosity "
      "wall_viscosity c l0 on pairs with a particle within r_e of a wall");
  f.wall_damping = s.real("wall_damping", 1.0, Range::non_negative(),
                          "wall_contact damped: damping rate in units of c / l0");
  f.wall_viscosity = s.real("wall_viscosity", 0.05, Range::non_negative(),
                            "wall_contact viscous: alpha of the near-wall closing-pair viscosity");
  f.wall_density = s.choice(
      "wall_density", {"added", "scaled"}, "added",
      "wall part of pnd: added, n_i + z(r) as eq. 20; scaled, n_i + z max(1, n_i / (n0 - z)): "
      "the virtual particles compressed like the fluid next to them (equal to "
      "eq. 20 at rest and in expansion)");
  f.corner_faces = s.boolean(
      "corner_faces", true,
      "at concave wall corners also apply the nearest other face (its z, mirror terms and "
      "repulsion, the doubly counted quadrant once); false: the nearest wall only, eq. 18");
  f.convex_corners = s.boolean(
      "convex_corners", true,
      "at convex wall corners count the solid's own virtual lattice in pnd and in the wall "
      "pressure term (eqs. 20 and 25 assume a half-plane there; false: as in the paper)");
  f.damping_time =
      s.real("damping_time", 0.0, Range::non_negative(),
             "initial damping phase T_d: velocities damped at a rate 20/T_d (1 - t/T_d) "
             "(quiet hydrostatic starts), s");
  for (auto& region :
       s.list("regions", "areas filled with particles at spacing l0, each on its own "
                         "lattice from its lower-left corner (l0/2 from its edges)"))
    f.regions.push_back(read_region(region));
  if (!doc && f.regions.empty()) s.fail("regions", "at least one region is required");
  if (auto d = s.block("domain", "particles leaving this box are removed and counted")) {
    f.domain_min = d->vec2("min", "lower-left corner, m");
    f.domain_max = d->vec2("max", "upper-right corner, m");
    if (!doc && (f.domain_max.x() <= f.domain_min.x() || f.domain_max.y() <= f.domain_min.y()))
      d->fail("max", "must lie above and right of min");
    d->finish();
  }
  if (!doc) {
    for (std::size_t i = 0; i < f.regions.size(); ++i) {
      Vec2 lo = f.regions[i][0], hi = f.regions[i][0];
      for (const auto& p : f.regions[i]) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
      const Vec2 size = hi - lo;
      if (f.l0 > size.minCoeff()) {
        std::ostringstream msg;
        msg << "particle spacing " << f.l0 << " m is larger than fluid region " << i << " ("
            << size.x() << " x " << size.y() << " m)";
        s.fail("l0", msg.str());
      }
    }
  }
  s.finish();
  return f;
}

MeshSpec read_mesh(Section s) {
  MeshSpec m;
  const bool doc = s.context().documenting();
  m.kind = s.choice("kind", {"rectangle", "gmsh"}, "",
                    "built-in structured T6 rectangle, or a Gmsh 4.1 file of 6-node triangles");
  if (doc || m.kind == "rectangle") {
    m.origin = s.vec2("origin", Vec2::Zero(), "lower-left corner, m");
    m.width = s.real("width", Range::positive(), "m");
    m.height = s.real("height", Range::positive(), "m");
    m.elements_x = s.integer("elements_x", Range::closed(1, 10000), "element columns");
    m.elements_y = s.integer("elements_y", Range::closed(1, 10000), "element rows");
  }
  if (doc || m.kind == "gmsh") m.file = s.file("file", "Gmsh .msh (format 4.1 ASCII)");
  s.finish();
  return m;
}

StructureSpec read_structure(Section s) {
  StructureSpec st;
  st.line = s.line();
  st.name = s.text("name", "structure name (probes refer to it)");
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
  s.finish();
  return st;
}

// Recording and one-way replay: the replayed file must cover every step of the run.
void read_one_way(Section& s, const TimeSpec& time, CouplingSpec& c) {
  const bool doc = s.context().documenting();
  c.record_interface = s.boolean("record_interface", false,
                                 "write DIR/interface.h5: per step the interface motion the fluid "
                                 "used and the loads the structure took");
  auto recorded = [&](const std::string& key, const std::string& scheme, const std::string& what) {
    if (!doc && c.scheme != scheme && s.has(key)) s.fail(key, "only for scheme " + scheme);
    if (!doc && c.scheme != scheme) return std::filesystem::path();
    const auto path = s.file(key, scheme + ": interface.h5 of a recorded run, its " + what +
                                      " interpolated linearly in time");
    if (doc) return path;
    const double step = time.dt.value_or(time.end);
    const double needed = std::ceil(time.end / step - 1e-9) * step; // the run's last step end
    std::ostringstream problem;
    try {
      const InterfaceHistory h(path);
      if (h.first_time() > 0.0 || h.last_time() < needed * (1.0 - 1e-12))
        problem << path.string() << ": records t = " << h.first_time() << " .. " << h.last_time()
                << " s, the run needs 0 .. " << needed << " s";
    } catch (const InputError& e) {
      problem << e.what();
    }
    if (!problem.str().empty()) s.fail(key, problem.str());
    return path;
  };
  c.motion = recorded("motion", "one_way_fluid", "interface motion");
  c.loads = recorded("loads", "one_way_structure", "interface loads");
}

CouplingSpec read_coupling(Section s, const TimeSpec& time) {
  CouplingSpec c;
  c.line = s.line();
  c.scheme = s.choice("scheme", {"css", "bgs", "one_way_fluid", "one_way_structure"}, "css",
                      "conventional serial staggered, block Gauss-Seidel iterations (eq. 69), the "
                      "fluid against a recorded motion, or the structure under recorded loads");
  c.predictor = s.choice("predictor", {"none", "second_order"}, "none",
                         "interface predictor for CSS (eqs. 63-65)");
  c.acceleration = s.choice("acceleration", {"none", "constant", "aitken", "iqn-ils"}, "aitken",
                            "BGS relaxation");
  c.tolerance = s.real("tolerance", 1e-4, Range::open(0.0, 1.0), "epsilon of eq. 69");
  c.max_iterations =
      s.integer("max_iterations", 200, Range::closed(1, 100000), "BGS iterations per step");
  c.omega = s.real("omega", 0.5, Range::left_open(0.0, 2.0),
                   "constant relaxation factor, or the first of aitken and iqn-ils");
  c.reuse = s.integer("reuse", 8, Range::closed(0, 100), "IQN-ILS: past steps kept");
  c.stop_on_unconverged =
      s.boolean("stop_on_unconverged", false, "stop the run at the first unconverged BGS step");
  c.substeps = s.integer("substeps", 1, Range::closed(1, 10000), "fluid steps per structure step");
  read_one_way(s, time, c);
  s.finish();
  return c;
}

CheckpointSpec read_checkpoint_spec(Section s) {
  CheckpointSpec c;
  c.line = s.line();
  if (auto n = s.optional_integer("interval_steps", Range::closed(1, 1e9),
                                  "write a checkpoint after every this many steps"))
    c.interval_steps = *n;
  c.interval_minutes = s.optional_real("interval_minutes", Range::positive(),
                                       "write a checkpoint after this much wall time, minutes");
  c.keep = s.integer("keep", 2, Range::closed(1, 1000), "newest checkpoints kept on disk");
  s.finish();
  if (!s.context().documenting() && !c.interval_steps && !c.interval_minutes)
    s.fail("", "give interval_steps, interval_minutes or both");
  return c;
}

// A structured T6 rectangle has (2 nx + 1)(2 ny + 1) nodes on a regular grid.
void check_rectangle_probe(const MeshSpec& m, const ProbeSpec& p, const Section& s) {
  const long nodes = (2L * m.elements_x + 1) * (2L * m.elements_y + 1);
  if (p.node && *p.node >= nodes)
    s.fail("node", "node " + std::to_string(*p.node) + " does not exist (the mesh has " +
                       std::to_string(nodes) + " nodes)");
  if (p.point) {
    const Vec2 h(m.width / (2 * m.elements_x), m.height / (2 * m.elements_y));
    const Vec2 grid = (*p.point - m.origin).cwiseQuotient(h);
    const Vec2 snapped = grid.array().round();
    const bool inside = snapped.x() >= 0 && snapped.x() <= 2 * m.elements_x && snapped.y() >= 0 &&
                        snapped.y() <= 2 * m.elements_y;
    if (!inside || (grid - snapped).cwiseAbs().maxCoeff() > 1e-6) {
      std::ostringstream msg;
      msg << "no node of structure '" << p.structure << "' at (" << p.point->x() << ", "
          << p.point->y() << ")";
      s.fail("point", msg.str());
    }
  }
}

// Checks that need the whole scene: names resolve, rectangles have the tags asked for.
void cross_check(Section& top, const Scene& scene, std::vector<Section>& structure_sections,
                 std::vector<Section>& probe_sections) {
  std::set<std::string> names;
  for (std::size_t i = 0; i < scene.structures.size(); ++i) {
    const auto& st = scene.structures[i];
    if (!names.insert(st.name).second)
      structure_sections[i].fail("name", "duplicate structure name '" + st.name + "'");
    if (st.mesh.kind == "rectangle") {
      const std::set<std::string> tags = {"left", "right", "bottom", "top"};
      auto check = [&](const std::vector<std::string>& list, const std::string& key) {
        for (const auto& t : list)
          if (!tags.count(t))
            structure_sections[i].fail(key, "unknown boundary tag '" + t +
                                                "' (a rectangle has left, right, bottom, top)");
      };
      check(st.clamped, "clamped");
      check(st.interface, "interface");
      for (const auto& l : st.loads)
        if (!tags.count(l.boundary))
          structure_sections[i].fail("loads", "unknown boundary tag '" + l.boundary + "'");
    }
    if (!st.clamped_motion.empty()) {
      if (st.clamped.empty())
        structure_sections[i].fail("clamped_motion", "needs clamped boundary tags to move");
      const auto w = std::find_if(scene.walls.begin(), scene.walls.end(),
                                  [&](const WallSpec& x) { return x.name == st.clamped_motion; });
      if (w == scene.walls.end())
        structure_sections[i].fail("clamped_motion", "no wall named '" + st.clamped_motion + "'");
      if (!w->motion)
        structure_sections[i].fail("clamped_motion",
                                   "wall '" + st.clamped_motion + "' has no motion");
    }
  }
  for (std::size_t i = 0; i < scene.output.probes.size(); ++i) {
    const auto& p = scene.output.probes[i];
    if (p.quantity.rfind("displacement", 0) == 0) {
      auto it = std::find_if(scene.structures.begin(), scene.structures.end(),
                             [&](const StructureSpec& st) { return st.name == p.structure; });
      if (it == scene.structures.end())
        probe_sections[i].fail("structure", "no structure named '" + p.structure + "'");
      if (it->mesh.kind == "rectangle") check_rectangle_probe(it->mesh, p, probe_sections[i]);
      if (p.quantity.ends_with("_tank") && it->clamped_motion.empty())
        probe_sections[i].fail("quantity", "'" + p.quantity + "' needs structure '" + p.structure +
                                               "' to have a clamped_motion");
    } else if (!scene.fluid) {
      probe_sections[i].fail("quantity", "'" + p.quantity + "' needs a fluid block");
    }
  }
  if (scene.coupling && (!scene.fluid || scene.structures.empty()))
    top.fail("coupling", "coupling needs a fluid block and at least one structure");
  if (!scene.fluid && scene.structures.empty())
    top.fail("", "the scene has neither a fluid nor a structure: nothing to simulate");
  if (scene.time.courant && !scene.fluid)
    top.fail("time", "courant needs a fluid block (give dt for structure-only scenes)");
}

Scene read_scene(Section top) {
  Scene scene;
  ReadContext& ctx = top.context();
  scene.name = top.text("name", "", "scene name, for logs (default: the file name)");
  scene.gravity = top.vec2("gravity", Vec2::Zero(), "gravitational acceleration, m/s^2");
  scene.time = read_time(top.required_block("time", "time span and step"));
  std::vector<Section> probe_sections;
  scene.output = read_output(top.required_block("output", "what is written, and how often"),
                             scene.time.end, probe_sections);
  const auto fluid_section = top.block("fluid", "EMPS fluid; absent: no fluid");
  if (fluid_section) scene.fluid = read_fluid(*fluid_section);
  for (auto& w : top.list("walls", "polygon walls (ERP), static or with prescribed motion"))
    scene.walls.push_back(read_wall(w));
  auto structure_sections = top.list("structures", "FE structures (T6, St. Venant-Kirchhoff)");
  for (auto& st : structure_sections) scene.structures.push_back(read_structure(st));
  if (auto c = top.block("coupling", "partitioned coupling; needs fluid and structures"))
    scene.coupling = read_coupling(*c, scene.time);
  if (auto c = top.block("checkpoint", "periodic checkpoints for fsi run --restart; absent: "
                                       "only on SIGINT/SIGTERM (docs/reliability.md)"))
    scene.checkpoint = read_checkpoint_spec(*c);
  top.finish();
  if (!ctx.documenting()) {
    cross_check(top, scene, structure_sections, probe_sections);
    check_resources(scene, fluid_section, structure_sections, available_memory());
  }
  return scene;
}

} // namespace

void fail_at(const Scene& scene, int line, const std::string& key, const std::string& what) {
  throw InputError(scene.path.string() + ":" + std::to_string(line) + ": " + key + ": " + what);
}

Scene load_scene(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string() + ": cannot open scene file");
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  return parse_scene(text, file, overrides);
}

Scene parse_scene(const std::string& text, const std::filesystem::path& file,
                  const std::vector<std::string>& overrides) {
  ReadContext ctx;
  ctx.file = file.string();
  ctx.dir = file.parent_path();
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::DeepRecursion& e) {
    throw InputError(file.string() + ":" + std::to_string(e.mark.line + 1) +
                     ": yaml: nested too deeply (" + std::to_string(e.depth()) + " levels)");
  } catch (const YAML::ParserException& e) {
    throw InputError(file.string() + ":" + std::to_string(e.mark.line + 1) + ": yaml: " + e.msg);
  }
  if (!root.IsMap()) throw InputError(file.string() + ":1: scene: expected a block of keys");
  for (const auto& o : overrides) apply_override(root, o, ctx);
  Scene scene = read_scene(Section(root, "", ctx));
  scene.path = file;
  scene.overrides = overrides;
  if (scene.name.empty()) scene.name = file.stem().string();
  return scene;
}

std::string scene_reference() {
  ReadContext ctx;
  ctx.collector = std::make_unique<std::vector<KeyDoc>>();
  read_scene(Section(YAML::Node(), "", ctx));
  std::ostringstream out;
  out << "# Scene file reference\n\n"
      << "Generated by `fsi reference` from the declarations the scene reader uses; do not edit.\n"
      << "SI units throughout. Unknown keys, wrong types and out-of-range values are errors\n"
      << "(`FILE:LINE: KEY: what is wrong`, exit status 2). Any key can be overridden with\n"
      << "`--set key.path=value` (list entries as `structures[0].material.density`).\n\n"
      << "| key | type | default | allowed | meaning |\n|---|---|---|---|---|\n";
  for (const auto& k : *ctx.collector)
    out << "| `" << k.path << "` | " << k.type << " | " << k.fallback << " | " << k.range << " | "
        << k.doc << " |\n";
  return out.str();
}

} // namespace fsi::app
