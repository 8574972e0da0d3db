#pragma once
// The shared hyperelastic laws (materials/material.hpp) under the FE solver's names.
#include "materials/material.hpp"
#include "materials/neo_hookean.hpp"
#include "materials/st_venant_kirchhoff.hpp"

namespace fsi::fem {

using materials::make_material;
using materials::Material;
using materials::MaterialModel;
using materials::MaterialOptions;
using materials::NeoHookean;
using materials::PlaneModel;
using materials::StVenantKirchhoff;
using materials::validate;

} // namespace fsi::fem
