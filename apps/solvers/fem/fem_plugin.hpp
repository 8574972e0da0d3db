#pragma once
// structures[].type: fem — the registration entry (apps/solvers/registry.cpp).
#include "fsi_app/solver_plugin.hpp"

namespace fsi::app::fem_plugin {

StructurePlugin plugin();

} // namespace fsi::app::fem_plugin
