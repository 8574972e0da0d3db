#pragma once
// The shared hyperelastic laws in 2-D and 3-D (materials/material.hpp) under the FE solver's names.
#include "materials/material.hpp"
#include "materials/neo_hookean.hpp"
#include "materials/st_venant_kirchhoff.hpp"

namespace fsi::fem {

using materials::make_material;
using materials::make_material_3d;
using materials::Material;
using materials::Material3;
using materials::MaterialModel;
using materials::MaterialOptions;
using materials::NeoHookean;
using materials::NeoHookean3;
using materials::PlaneModel;
using materials::StVenantKirchhoff;
using materials::StVenantKirchhoff3;
using materials::validate;

} // namespace fsi::fem
