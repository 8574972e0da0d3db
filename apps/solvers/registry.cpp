// The one registration list of solver plug-ins (apps/include/fsi_app/solver_plugin.hpp). A new
// solver adds its folder under apps/solvers/, one line here and its sources in apps/CMakeLists.txt.
// The first entry of each list is the default `type`.
#include "emps/emps_plugin.hpp"
#include "fem/fem_plugin.hpp"

#include <algorithm>

namespace fsi::app {

const std::vector<FluidPlugin>& fluid_plugins() {
  static const std::vector<FluidPlugin> list{emps_plugin::plugin()};
  return list;
}

const std::vector<StructurePlugin>& structure_plugins() {
  static const std::vector<StructurePlugin> list{fem_plugin::plugin()};
  return list;
}

namespace {
template <class Plugin> const Plugin* find(const std::vector<Plugin>& list, std::string_view name) {
  const auto it =
      std::find_if(list.begin(), list.end(), [&](const Plugin& p) { return p.name == name; });
  return it == list.end() ? nullptr : &*it;
}
} // namespace

const FluidPlugin* find_fluid_plugin(std::string_view name) {
  return find(fluid_plugins(), name);
}

const StructurePlugin* find_structure_plugin(std::string_view name) {
  return find(structure_plugins(), name);
}

} // namespace fsi::app
