// The fluid and structure blocks of a scene file: the type picks the plug-in that reads them.
#include "scene_blocks.hpp"

#include "fsi_app/solver_plugin.hpp"

#include <set>
#include <string>
#include <type_traits>
#include <vector>

namespace fsi::app {

namespace {

// Another type's block (fluid.emps: {...} in a fluid of type sph) is read by that type's
// plug-in, with the keys of the enclosing block that plug-in declares, so its keys are checked;
// then it is set aside. A structure block without its own geometry (a 3-D tlsph block of dp
// beside the FE box) is read as that type reads the entry: through its adopt.
template <class Plugin> void check_set_aside(Section& s, const Plugin& p) {
  Section entry(s.node(), s.path(), s.context(), s.line());
  if constexpr (std::is_same_v<Plugin, StructurePlugin>)
    if (p.adopt) p.adopt(entry);
  const std::set<std::string> own = declared_keys(p.read);
  YAML::Node view(YAML::NodeType::Map);
  for (auto it = entry.node().begin(); it != entry.node().end(); ++it)
    if (own.count(it->first.Scalar()) || it->first.Scalar() == p.name)
      view.force_insert(it->first, it->second);
  Section other(view, s.path(), s.context(), s.line());
  other.lift(p.name);
  p.read(other);
  other.finish();
  s.set_aside(p.name);
}

} // namespace

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

template void read_solver_block(Section&, const std::vector<FluidPlugin>&, FluidBlock&,
                                const std::string&);
template void read_solver_block(Section&, const std::vector<StructurePlugin>&, StructureBlock&,
                                const std::string&);

} // namespace fsi::app
