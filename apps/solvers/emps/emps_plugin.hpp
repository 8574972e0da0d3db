#pragma once
// fluid.type: emps — the registration entry (apps/solvers/registry.cpp).
#include "fsi_app/solver_plugin.hpp"

namespace fsi::app::emps_plugin {

FluidPlugin plugin();

} // namespace fsi::app::emps_plugin
