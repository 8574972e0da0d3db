// Checks of a scene that need the whole of it: names resolve, then each plug-in's own.
#include "scene_blocks.hpp"

#include "fsi_app/solver_plugin.hpp"

#include <algorithm>
#include <cctype>
#include <set>
#include <string>

namespace fsi::app {

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

} // namespace fsi::app
