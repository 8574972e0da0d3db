// The one registration list of solver plug-ins (apps/include/fsi_app/solver_plugin.hpp). A new
// solver adds its folder under apps/solvers/, one line here and its sources in apps/CMakeLists.txt.
// The first entry of each list is the default `type`.
#include "emps/emps_plugin.hpp"
#include "fem/fem_plugin.hpp"
#include "sph/sph_plugin.hpp"
#include "tlsph/tlsph_plugin.hpp"

#include <algorithm>
#include <stdexcept>

namespace fsi::app {

namespace {
std::vector<FluidPlugin>& fluids() {
  static std::vector<FluidPlugin> list{emps_plugin::plugin(), sph_plugin::plugin()};
  return list;
}
std::vector<StructurePlugin>& structures() {
  static std::vector<StructurePlugin> list{fem_plugin::plugin(), tlsph_plugin::plugin()};
  return list;
}
} // namespace

const std::vector<FluidPlugin>& fluid_plugins() {
  return fluids();
}
const std::vector<StructurePlugin>& structure_plugins() {
  return structures();
}
void add_fluid_plugin(FluidPlugin plugin) {
  fluids().push_back(std::move(plugin));
}
void add_structure_plugin(StructurePlugin plugin) {
  structures().push_back(std::move(plugin));
}

namespace {
template <class Plugin> const Plugin* find(const std::vector<Plugin>& list, std::string_view name) {
  const auto it =
      std::find_if(list.begin(), list.end(), [&](const Plugin& p) { return p.name == name; });
  return it == list.end() ? nullptr : &*it;
}
} // namespace

std::set<std::string>
declared_keys(const std::function<std::shared_ptr<const SolverSpec>(Section&)>& read) {
  ReadContext ctx;
  ctx.collector = std::make_unique<std::vector<KeyDoc>>();
  Section doc(YAML::Node(), "", ctx);
  read(doc);
  std::set<std::string> keys;
  for (const KeyDoc& k : *ctx.collector) keys.insert(k.path.substr(0, k.path.find_first_of(".[")));
  return keys;
}

const FluidPlugin* find_fluid_plugin(std::string_view name) {
  return find(fluid_plugins(), name);
}

const StructurePlugin* find_structure_plugin(std::string_view name) {
  return find(structure_plugins(), name);
}

// The 3-D coupling of a part that has none: a caller asked what the plug-in does not give.
coupling::FluidSolver3& FluidPart::coupling_solver3() {
  throw std::logic_error("fluid part: this fluid type has no 3-D coupling (coupling_solver3)");
}
const InterfaceMesh3& StructurePart::interface_mesh3() const {
  throw std::logic_error("structure '" + name() + "': its type has no 3-D interface");
}
coupling::StructureSolver3& StructurePart::coupling_solver3() {
  throw std::logic_error("structure '" + name() + "': its type has no 3-D coupling");
}

} // namespace fsi::app
