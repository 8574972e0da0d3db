// A scene file read whole: its top-level keys and time block, the blocks' readers
// (scene_blocks.hpp) put together, --set overrides applied first, then the checks across blocks.
#include "fsi_app/scene.hpp"

#include "scene_blocks.hpp"

#include "fsi/core/error.hpp"
#include "fsi_app/overrides.hpp"
#include "fsi_app/resources.hpp"
#include "fsi_app/scene_reader.hpp"
#include "fsi_app/solver_plugin.hpp"

#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

namespace fsi::app {

namespace {

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

int read_dimension(Section& top) {
  return top.integer("dimension", 2, Range::closed(2, 3),
                     "2 or 3: every point and vector of the scene has this many coordinates; "
                     "3 takes structures of type fem (T10 elements) or tlsph (a box of "
                     "particles), or a fluid of type sph (boxes in an open box tank), not yet "
                     "a fluid and a structure together");
}

} // namespace

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

} // namespace fsi::app
