#pragma once
// The `material` block of a solid's scene entry, shared by the solid plug-ins (fem, tlsph).
#include "fsi_app/scene_reader.hpp"
#include "materials/material.hpp"

namespace fsi::app {

/// Reads the keys materials/ declares (visit_options) and checks its rule across keys
/// (neo_hookean: plane strain only; in 3-D no plane); every other key of the block is an error.
void read_material(Section& block, materials::MaterialOptions& options);

} // namespace fsi::app
