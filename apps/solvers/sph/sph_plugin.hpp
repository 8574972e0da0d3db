#pragma once
// fluid.type: sph — the registration entry (apps/solvers/registry.cpp).
#include "fsi_app/solver_plugin.hpp"

namespace fsi::app::sph_plugin {

FluidPlugin plugin();

} // namespace fsi::app::sph_plugin
