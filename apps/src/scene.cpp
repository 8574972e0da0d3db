#include "fsi_app/scene.hpp"

#include "coupling/registry.hpp"
#include "fsi/core/error.hpp"
#include "fsi/core/format.hpp"
#include "fsi_app/output/interface_history.hpp"
#include "fsi_app/overrides.hpp"
#include "fsi_app/resources.hpp"
#include "fsi_app/scene_reader.hpp"
#include "fsi_app/solver_plugin.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>
#include <type_traits>
#include <utility>
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
                              "particle, with the viscous limit (fluid and coupled scenes: "
                              "the coupling step is the fluid's)");
  if (!s.context().documenting()) {
    if (t.dt && t.courant) s.fail("courant", "give either dt or courant, not both");
    if (!t.dt && !t.courant) s.fail("", "one of dt or courant is required");
    if (t.dt && *t.dt > t.end) s.fail("dt", "is larger than time.end");
    // At most 1e9 steps (docs/reliability.md, "Time steps"); also keeps the count in a long.
    if (t.dt && !(t.end / *t.dt <= 1e9)) {
      std::ostringstream n;
      n << t.end / *t.dt;
      s.fail("dt", "time.end / time.dt = " + n.str() + " steps; a run takes at most 1e9 steps");
    }
  }
  s.finish();
  return t;
}

// Field names and probe quantities are the plug-ins' (each declares its own); a quantity of a
// structure plug-in needs the probe's `structure` key.
template <class Plugins>
void add_unique(std::vector<std::string>& out, const Plugins& plugins,
                std::vector<std::string> Plugins::value_type::*list) {
  for (const auto& p : plugins)
    for (const auto& name : p.*list)
      if (std::find(out.begin(), out.end(), name) == out.end()) out.push_back(name);
}

std::vector<std::string> field_names() {
  std::vector<std::string> out;
  add_unique(out, fluid_plugins(), &FluidPlugin::fields);
  add_unique(out, structure_plugins(), &StructurePlugin::fields);
  return out;
}

std::vector<std::string> structure_quantities() {
  std::vector<std::string> out;
  add_unique(out, structure_plugins(), &StructurePlugin::probe_quantities);
  return out;
}

std::vector<std::string> probe_quantities() {
  std::vector<std::string> out;
  add_unique(out, fluid_plugins(), &FluidPlugin::probe_quantities);
  add_unique(out, structure_plugins(), &StructurePlugin::probe_quantities);
  return out;
}
const std::vector<std::string> kForceParts = {"total", "pressure", "repulsive", "viscous"};

ProbeSpec read_probe(Section s) {
  ProbeSpec p;
  p.line = s.line();
  p.key = s.path();
  p.name = s.text("name", "column name in probes.csv (letters, digits, _)");
  p.quantity =
      s.choice("quantity", probe_quantities(), "",
               "what is sampled: a node's displacement; a node's displacement in the "
               "frame of the wall its structure is clamped to (clamped_motion: the "
               "rigid motion undone, x and y along the tank's axes); the surge front "
               "(largest x of particles with pnd >= n0/2, i.e. not spray); the pressure "
               "at a point (MPS-weighted mean within r_e); mean_pressure, the plain mean "
               "over the particles inside the box min..max; mean_speed and "
               "kinetic_energy (J per m of depth; 3-D: J) of all particles; velocity_x|y|z, "
               "the kernel-weighted velocity at a point (type sph); wall_force_x|y, "
               "the fluid's force on the coupled structure (on all walls without one), "
               "N/m, of the last step; (3-D, type emps) particles, their count, and wall_gap, "
               "the smallest distance of a particle centre to its nearest wall, m");
  p.structure = s.text("structure", "", "structure name, for displacement probes");
  p.node = s.optional_integer("node", Range::non_negative(), "FE node index (or give point)");
  const std::string point_doc = "reference position of the FE node or the TL-SPH point, or the "
                                "fluid point, m (dimension 3: [x, y, z])";
  if (s.context().dimension == 3 && !s.context().documenting())
    p.point3 = s.optional_vec3("point", point_doc);
  else
    p.point = s.optional_vec2("point", point_doc);
  const std::string min_doc = "mean_pressure: lower-left corner of the box, m ([x, y, z] in 3-D)";
  const std::string max_doc = "mean_pressure: upper-right corner of the box, m ([x, y, z] in 3-D)";
  if (s.context().dimension == 3 && !s.context().documenting()) {
    p.box3_min = s.optional_vec3("min", min_doc);
    p.box3_max = s.optional_vec3("max", max_doc);
  } else {
    p.box_min = s.optional_vec2("min", min_doc);
    p.box_max = s.optional_vec2("max", max_doc);
  }
  p.part = s.choice("part", kForceParts, "total",
                    "wall_force: the wall term carried: pressure (mirror, eqs. 25-26), repulsive "
                    "(eq. 27 and wall damping), viscous (eq. 24) or their total");
  p.interpolate = s.boolean("interpolate", false,
                            "(type tlsph) displacement at point by the kernel interpolation of "
                            "the particles' displacements (linear correction, reference "
                            "configuration); false: the particle nearest to point (type fem: "
                            "the node at point either way, the FE interpolation there)");
  if (!s.context().documenting()) {
    const bool ok_name = !p.name.empty() && std::all_of(p.name.begin(), p.name.end(), [](char c) {
      return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
    });
    if (!ok_name) s.fail("name", "'" + p.name + "' is not a valid column name");
    if (p.name == "time") // probes.csv's first column, and the Python result's time key
      s.fail("name",
             "'time' is reserved (the first column of probes.csv); name the probe otherwise");
    const auto on = structure_quantities();
    const bool on_structure = std::find(on.begin(), on.end(), p.quantity) != on.end();
    if (on_structure && p.structure.empty()) s.fail("structure", "required key missing");
    if (p.interpolate && !on_structure)
      s.fail("interpolate", "only a structure's displacement probes interpolate");
    if ((p.quantity == "displacement_z" || p.quantity == "velocity_z") &&
        s.context().dimension != 3)
      s.fail("quantity", p.quantity + " needs a 3-D scene (dimension: 3)");
    const bool at_point = p.quantity == "pressure" || p.quantity.starts_with("velocity_");
    if (at_point && !p.point && !p.point3) s.fail("point", "required key missing");
    if (p.quantity == "mean_pressure") {
      if (!p.box_min && !p.box3_min) s.fail("min", "required key missing");
      if (!p.box_max && !p.box3_max) s.fail("max", "required key missing");
      if (p.box3_min && !((*p.box3_max - *p.box3_min).minCoeff() > 0.0))
        s.fail("max", "must lie above min on every axis");
      if (p.box_min && (p.box_max->x() <= p.box_min->x() || p.box_max->y() <= p.box_min->y()))
        s.fail("max", "must lie above and right of min");
    }
  }
  s.finish();
  return p;
}

/// The most frames a run may write (docs/reliability.md, issue 41).
constexpr double kMaxFrames = 1e5;

OutputSpec read_output(Section s, double end_time, std::vector<Section>& probe_sections) {
  OutputSpec o;
  o.interval = s.real("interval", Range::positive(), "simulated time between frames, s");
  const std::vector<std::string> known = field_names();
  o.fields = s.names("fields", known,
                     "fields written to fields.h5 (particle positions and mesh geometry always)");
  for (const auto& f : o.fields)
    if (std::find(known.begin(), known.end(), f) == known.end()) {
      std::string list;
      for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
      s.fail("fields", "unknown field '" + f + "' (known: " + list + ")");
    }
  std::set<std::string> names;
  probe_sections = s.list("probes", "sampled every frame into probes.csv");
  for (auto& probe : probe_sections) {
    o.probes.push_back(read_probe(probe));
    if (!s.context().documenting() && !names.insert(o.probes.back().name).second)
      probe.fail("name", "duplicate probe name '" + o.probes.back().name + "'");
  }
  if (!s.context().documenting() && o.interval > end_time)
    s.fail("interval", "is larger than time.end");
  // Issue 41: 1e-12 s with Courant stepping wrote 2,029 frames (42 MB) in 25 s towards 1e12;
  // what cannot finish is refused before step 0 (each frame is also at least one step).
  if (!s.context().documenting() && !(end_time / o.interval <= kMaxFrames))
    s.fail("interval", "time.end / output.interval = " + significant(end_time / o.interval, 3) +
                           " frames; a run writes at most " + significant(kMaxFrames, 3) +
                           " (give a larger interval)");
  s.finish();
  return o;
}

// The keys of a motion's profile s(t) after kind, dof and pivot (read_motion, read_motion3).
void read_profile(Section& s, MotionSpec& m) {
  const bool doc = s.context().documenting();
  if (doc || m.kind == "sinusoid") {
    m.amplitude = s.real("amplitude", Range::any(), "rad for rotation, m for translation");
    m.period = s.real("period", Range::positive(), "s");
    m.phase = s.real("phase", 0.0, Range::any(), "rad");
    // Issue 41: a period so short that 2 pi / period or the acceleration amplitude
    // amplitude (2 pi / period)^2 overflows makes the wall NaN (5e-324 passes "> 0").
    const double omega = 2.0 * M_PI / m.period;
    if (!doc && !(std::isfinite(omega) && std::isfinite(std::abs(m.amplitude) * omega * omega) &&
                  std::isfinite(omega * omega)))
      s.fail("period", significant(m.period, 6) + " s with amplitude " +
                           significant(m.amplitude, 6) +
                           ": the motion's acceleration amplitude * (2 pi / period)^2 is not "
                           "finite; give a longer period");
  }
  if (doc || m.kind == "table") {
    m.table = s.file("table", "CSV with header; columns time (s) and value");
    const std::string unit = s.choice("unit", {"deg", "rad", "m"}, "rad", "unit of the values");
    const double scale =
        s.real("scale", 1.0, Range::any(),
               "factor on the values, e.g. -1 for a table whose positive angles turn clockwise "
               "(the scene's turn counter-clockwise)");
    m.table_scale = scale * (unit == "deg" ? M_PI / 180.0 : 1.0);
    m.hold = s.boolean("hold", false,
                       "hold the table's first value before its first time and its last value "
                       "after its last; without it the table must cover 0 .. time.end");
    if (!doc && (unit == "m") != (m.dof != "rotation"))
      s.fail("unit", "'" + unit + "' does not match dof '" + m.dof + "'");
  }
  s.finish();
}

std::string motion_kind(Section& s) {
  return s.choice("kind", {"sinusoid", "table"}, "",
                  "sinusoid: amplitude sin(2 pi t / period + phase); table: CSV time,value");
}

MotionSpec read_motion(Section s) {
  MotionSpec m;
  m.kind = motion_kind(s);
  m.dof = s.choice("dof", {"rotation", "x", "y"}, "rotation",
                   "rotation about pivot, or translation along x or y");
  m.pivot = s.vec2("pivot", Vec2::Zero(), "rotation centre in the scene frame, m");
  read_profile(s, m);
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
  // Issue 41: the closing segment of a closed polyline too (it failed later, naming no key).
  if (!s.context().documenting() && w.closed && w.polyline.size() > 2 &&
      (w.polyline.front() - w.polyline.back()).norm() == 0.0)
    s.fail("polyline", "the last point " + std::to_string(w.polyline.size() - 1) +
                           " is the first (closed: true joins them by a zero-length segment); "
                           "drop the last point");
  s.finish();
  return w;
}

// The first and last time of a recorded interface.h5 of the scene's dimension.
std::pair<double, double> recorded_times(const std::filesystem::path& path, int dimension) {
  if (dimension == 3) {
    const InterfaceHistory3 h(path);
    return {h.first_time(), h.last_time()};
  }
  const InterfaceHistory h(path);
  return {h.first_time(), h.last_time()};
}

// Recording and one-way replay: the replayed file must cover every step of the run.
void read_one_way(Section& s, const TimeSpec& time, CouplingSpec& c) {
  const bool doc = s.context().documenting();
  c.record_interface = s.boolean("record_interface", false,
                                 "write DIR/interface.h5: per step the interface motion the fluid "
                                 "used and the loads the structure took");
  const coupling::SchemeNeeds needs =
      doc ? coupling::SchemeNeeds{} : coupling::builtin_registry().scheme_needs(c.options.scheme);
  auto recorded = [&](const std::string& key, bool needed, const std::string& what) {
    if (!doc && !needed && s.has(key))
      s.fail(key, "scheme '" + c.options.scheme + "' replays no recorded " + what);
    if (!doc && !needed) return std::filesystem::path();
    const auto path = s.file(key, "interface.h5 of a recorded run, its " + what +
                                      " interpolated linearly in time (schemes that replay it)");
    if (doc) return path;
    const double step = time.dt.value_or(time.end);
    const double last = std::ceil(time.end / step - 1e-9) * step; // the run's last step end
    std::ostringstream problem;
    try {
      const auto [first, end] = recorded_times(path, s.context().dimension);
      if (first > 0.0 || end < last * (1.0 - 1e-12))
        problem << path.string() << ": records t = " << first << " .. " << end
                << " s, the run needs 0 .. " << last << " s";
    } catch (const InputError& e) {
      problem << e.what();
    }
    if (!problem.str().empty()) s.fail(key, problem.str());
    return path;
  };
  c.motion = recorded("motion", needs.prescribed_motion, "interface motion");
  c.loads = recorded("loads", needs.prescribed_loads, "interface loads");
}

CouplingSpec read_coupling(Section s, const TimeSpec& time) {
  CouplingSpec c;
  c.line = s.line();
  OptionReader reader(s);
  coupling::visit_options(c.options, coupling::builtin_registry(), reader);
  read_one_way(s, time, c);
  if (!s.context().documenting()) try { // the rules beyond each key's range
      coupling::validate_options(c.options, coupling::builtin_registry());
    } catch (const InputError& e) {
      s.fail("", e.what());
    }
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

// Checks that need the whole scene: names resolve, then each plug-in's own checks.
void cross_check(Section& top, const Scene& scene, std::optional<Section>& fluid_section,
                 std::vector<Section>& structure_sections, std::vector<Section>& probe_sections) {
  std::set<std::string> names;
  for (std::size_t i = 0; i < scene.structures.size(); ++i) {
    const std::string& name = scene.structures[i].name;
    // The name is a group of fields.h5 and checkpoints, a grid of fields.xmf and a run.json key.
    const bool ok = !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
      return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
    });
    if (!ok)
      structure_sections[i].fail("name", "'" + name +
                                             "' is not a valid name (letters, digits, _ and -: "
                                             "it names output groups)");
    if (name == "particles")
      structure_sections[i].fail("name", "'particles' is reserved (the fluid's grid in "
                                         "fields.h5); name the structure otherwise");
    if (!names.insert(name).second)
      structure_sections[i].fail("name", "duplicate structure name '" + name + "'");
  }
  for (std::size_t i = 0; i < scene.output.probes.size(); ++i) {
    const auto& p = scene.output.probes[i];
    if (!p.structure.empty()) {
      const auto it =
          std::find_if(scene.structures.begin(), scene.structures.end(),
                       [&](const StructureBlock& st) { return st.name == p.structure; });
      if (it == scene.structures.end())
        probe_sections[i].fail("structure", "no structure named '" + p.structure + "'");
      const auto& q = find_structure_plugin(it->type)->probe_quantities;
      if (std::find(q.begin(), q.end(), p.quantity) == q.end())
        probe_sections[i].fail("quantity", "'" + p.quantity + "' is not a probe of structure '" +
                                               p.structure + "' (type " + it->type + ")");
    } else {
      if (!scene.fluid)
        probe_sections[i].fail("quantity", "'" + p.quantity + "' needs a fluid block");
      const auto& q = find_fluid_plugin(scene.fluid->type)->probe_quantities;
      if (std::find(q.begin(), q.end(), p.quantity) == q.end())
        probe_sections[i].fail("quantity", "'" + p.quantity + "' is not a probe of fluid type " +
                                               scene.fluid->type);
    }
  }
  if (scene.coupling && (!scene.fluid || scene.structures.empty()))
    top.fail("coupling", "coupling needs a fluid block and at least one structure");
  if (!scene.fluid && scene.structures.empty())
    top.fail("", "the scene has neither a fluid nor a structure: nothing to simulate");
  if (scene.time.courant && !scene.fluid)
    top.fail("time", "courant needs a fluid block (give dt for structure-only scenes)");
  if (scene.fluid)
    find_fluid_plugin(scene.fluid->type)->check(scene, *fluid_section, probe_sections);
  for (std::size_t i = 0; i < scene.structures.size(); ++i)
    find_structure_plugin(scene.structures[i].type)
        ->check(scene, i, structure_sections[i], probe_sections);
}

// Another type's block (fluid.emps: {...} in a fluid of type sph) is read by that type's
// plug-in, with the keys of the enclosing block that plug-in declares, so its keys are checked;
// then it is set aside.
template <class Plugin> void check_set_aside(Section& s, const Plugin& p) {
  const std::set<std::string> own = declared_keys(p.read);
  YAML::Node view(YAML::NodeType::Map);
  for (auto it = s.node().begin(); it != s.node().end(); ++it)
    if (own.count(it->first.Scalar()) || it->first.Scalar() == p.name)
      view.force_insert(it->first, it->second);
  Section other(view, s.path(), s.context(), s.line());
  other.lift(p.name);
  p.read(other);
  other.finish();
  s.set_aside(p.name);
}

// A solver block: its type picks the plug-in, which reads the rest. A block named after a type
// holds keys for that type only: the chosen type's is read as part of the solver block, the
// others' are checked and set aside, so one scene runs with any type by `--set ...type=`. In
// documentation mode every plug-in's keys are listed, each marked with its type.
template <class Plugin, class Block>
void read_solver_block(Section& s, const std::vector<Plugin>& plugins, Block& block,
                       const std::string& what) {
  std::vector<std::string> types;
  for (const auto& p : plugins) types.push_back(p.name);
  block.line = s.line();
  block.type = s.choice("type", types, types.front(), what + " solver (apps/solvers/<type>/)");
  if (!s.context().documenting()) {
    if constexpr (std::is_same_v<Plugin, StructurePlugin>)
      for (const auto& p : plugins)
        if (p.name == block.type && p.adopt) p.adopt(s);
    for (const auto& p : plugins)
      if (p.name != block.type && s.has(p.name)) check_set_aside(s, p);
    s.lift(block.type);
    for (const auto& p : plugins)
      if (p.name == block.type) block.spec = p.read(s);
    return;
  }
  auto& docs = *s.context().collector;
  for (const auto& p : plugins) {
    docs.push_back({s.path() + "." + p.name, "block", "optional", "",
                    "keys for type " + p.name + " only: read as keys of " + s.path() +
                        " when type is " + p.name + ", checked and set aside otherwise"});
    const std::size_t first = docs.size();
    p.read(s);
    for (std::size_t k = first; k < docs.size(); ++k)
      docs[k].doc = "(type " + p.name + ") " + docs[k].doc;
  }
}

int read_dimension(Section& top) {
  return top.integer("dimension", 2, Range::closed(2, 3),
                     "2 or 3: every point and vector of the scene has this many coordinates; "
                     "3 takes structures of type fem (T10 elements) or tlsph (a box of "
                     "particles), or a fluid of type sph (boxes in an open box tank), not yet "
                     "a fluid and a structure together");
}

Scene read_scene(Section top) {
  Scene scene;
  ReadContext& ctx = top.context();
  scene.name = top.text("name", "", "scene name, for logs (default: the file name)");
  scene.dimension = ctx.dimension = read_dimension(top);
  const std::string gravity_doc = "gravitational acceleration, m/s^2 (dimension 3: [x, y, z])";
  if (scene.dimension == 3)
    scene.gravity3 = top.vec3("gravity", Vec3::Zero(), gravity_doc);
  else
    scene.gravity = top.vec2("gravity", Vec2::Zero(), gravity_doc);
  scene.time = read_time(top.required_block("time", "time span and step"));
  std::vector<Section> probe_sections;
  scene.output = read_output(top.required_block("output", "what is written, and how often"),
                             scene.time.end, probe_sections);
  auto fluid_section = top.block("fluid", "the fluid; absent: no fluid");
  if (fluid_section) {
    scene.fluid.emplace();
    read_solver_block(*fluid_section, fluid_plugins(), *scene.fluid, "fluid");
    fluid_section->finish();
  }
  for (auto& w : top.list("walls", "polygon walls (ERP), static or with prescribed motion")) {
    if (scene.dimension == 3)
      top.fail("walls", "3-D wall polylines are not yet available (a 3-D SPH fluid takes "
                        "fluid.tank)");
    scene.walls.push_back(read_wall(w));
  }
  auto structure_sections = top.list("structures", "the structures");
  if (scene.dimension == 3 && scene.fluid && !structure_sections.empty() &&
      !find_fluid_plugin(scene.fluid->type)->build3)
    fluid_section->fail("type", "fluid type " + scene.fluid->type +
                                    " is not yet coupled to structures in 3-D");
  for (auto& st : structure_sections) {
    StructureBlock& b = scene.structures.emplace_back();
    b.key = st.path();
    b.name = st.text("name", "structure name (probes refer to it)");
    read_solver_block(st, structure_plugins(), b, "structure");
    st.finish();
  }
  if (auto c = top.block("coupling", "partitioned coupling; needs fluid and structures"))
    scene.coupling = read_coupling(*c, scene.time);
  if (auto c = top.block("checkpoint", "periodic checkpoints for fsi run --restart; absent: "
                                       "only on SIGINT/SIGTERM (docs/reliability.md)"))
    scene.checkpoint = read_checkpoint_spec(*c);
  top.finish();
  if (!ctx.documenting()) {
    cross_check(top, scene, fluid_section, structure_sections, probe_sections);
    check_resources(scene, fluid_section, structure_sections, available_memory());
  }
  return scene;
}

} // namespace

MotionSpec read_motion3(Section s) {
  MotionSpec m;
  m.kind = motion_kind(s);
  m.dof = s.choice("dof", {"rotation", "x", "y", "z"}, "rotation",
                   "rotation about axis through pivot, or translation along x, y or z");
  m.axis =
      s.vec3("axis", Vec3::UnitZ(),
             "rotation axis (normalised; default [0, 0, 1]), right-handed: counter-clockwise seen "
             "from its tip");
  m.pivot3 = s.vec3("pivot", Vec3::Zero(),
                    "a point of the rotation axis in the scene frame (default the origin), m");
  if (!s.context().documenting() && !(m.axis.norm() > 0.0)) s.fail("axis", "is zero");
  read_profile(s, m);
  return m;
}

void fail_at(const Scene& scene, int line, const std::string& key, const std::string& what) {
  throw InputError(scene.path.string() + ":" + std::to_string(line) + ": " + key + ": " + what);
}

namespace {
/// FNV-1a 64 of the tree as YAML without time.end (the tree is read already: changed in place).
std::uint64_t scene_digest(YAML::Node& root) {
  if (root["time"].IsMap()) root["time"].remove("end");
  YAML::Emitter out;
  out << root;
  std::uint64_t h = 14695981039346656037ULL;
  for (const char c : std::string(out.c_str())) {
    h ^= static_cast<unsigned char>(c);
    h *= 1099511628211ULL;
  }
  return h;
}
} // namespace

Scene load_scene(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  return parse_scene(read_scene_file(file), file, overrides);
}

Scene parse_scene(const std::string& text, const std::filesystem::path& file,
                  const std::vector<std::string>& overrides) {
  ReadContext ctx;
  ctx.file = file.string();
  ctx.dir = file.parent_path();
  YAML::Node root = load_scene_yaml(text, file.string());
  if (!root.IsMap()) throw InputError(file.string() + ":1: scene: expected a block of keys");
  unshare_override_paths(root, overrides, [&] { return load_scene_yaml(text, file.string()); });
  for (const auto& o : overrides) apply_override(root, o, ctx);
  Scene scene = read_scene(Section(root, "", ctx));
  scene.digest = scene_digest(root);
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
      << "A solver block's `type` picks its solver. Keys for one type only may sit in a block\n"
      << "named after it (`fluid.emps`, `fluid.sph`, `structures[].fem`, `structures[].tlsph`):\n"
      << "the chosen type's is read as keys of the solver block, the others are checked and set\n"
      << "aside, so one scene runs with any fluid and any structure by `--set fluid.type=sph\n"
      << "--set structures[0].type=tlsph` (tests/apps/data/tiny_any_pair.yaml).\n\n"
      << "A structure given for one type only takes the other type's geometry from it, so\n"
      << "`--set structures[N].type=tlsph` or `=fem` alone switches it: without a `region`, the\n"
      << "TL-SPH solid fills the FE mesh's outline (a rectangle, or a Gmsh mesh's boundary) at\n"
      << "`dp` = the mesh's node spacing unless `dp` is given, each FE `clamped` side (straight,\n"
      << "along an axis) continued 4 rows outwards into a clamped box; without a `mesh`, the FE\n"
      << "type meshes a TL-SPH rectangle `{min, max}` with nodes about dp apart, a clamped box\n"
      << "holding a side's strip becoming that clamped side, or reads a Gmsh `region.file`.\n"
      << "What does not translate (FE `loads`, a slanted clamped side, a TL-SPH polygon) is an\n"
      << "error naming the key (apps/solvers/structure_geometry.hpp).\n\n"
      << "A scene of `dimension: 3` reads every point and vector as [x, y, z] (y up, as in 2-D)\n"
      << "and takes structures of type fem (T10 elements; mesh kind box or gmsh, linear\n"
      << "solver cholmod by default, no `plane`, loads on faces as a total force or a pressure)\n"
      << "or tlsph (a box `region: {min, max}` of particles, fixed clamped boxes; an FE box\n"
      << "mesh is read as that box, its clamped sides continued 4 rows outwards as in 2-D; no\n"
      << "polygon, Gmsh region or interface), or a fluid of type sph (`regions` and `domain` as\n"
      << "boxes `{min, max}` in [x, y, z], the walls an open box tank `fluid.tank`); not yet a\n"
      << "fluid and a structure together, nor wall polylines, the sph `inflow` and `interface_*`\n"
      << "keys or another fluid type.\n\n"
      << "| key | type | default | allowed | meaning |\n|---|---|---|---|---|\n";
  for (const auto& k : *ctx.collector)
    out << "| `" << k.path << "` | " << k.type << " | " << k.fallback << " | " << k.range << " | "
        << k.doc << " |\n";
  return out.str();
}

} // namespace fsi::app
