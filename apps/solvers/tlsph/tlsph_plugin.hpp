#pragma once
// structures[].type: tlsph — the registration entry (apps/solvers/registry.cpp).
#include "fsi_app/solver_plugin.hpp"

namespace fsi::app::tlsph_plugin {

StructurePlugin plugin();

} // namespace fsi::app::tlsph_plugin
