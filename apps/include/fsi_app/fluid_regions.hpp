#pragma once
// The fluid regions of a scene filled with particles, for every particle fluid's plug-in.
#include "fsi_app/solver_plugin.hpp"

namespace fsi::app {

/// Each region on its own lattice at spacing l0, l0/2 from the scene's walls (as written) and
/// outside the `solid` areas. InputError (scene file and line) when no particle fits.
std::vector<Vec2> fill_regions(const Scene& scene, const std::vector<Polygon>& regions, double l0,
                               const std::vector<Polygon>& solid);

} // namespace fsi::app
