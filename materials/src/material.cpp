#include "materials/material.hpp"
#include "materials/neo_hookean.hpp"
#include "materials/st_venant_kirchhoff.hpp"

#include <cmath>
#include <string>

#include "fsi/core/error.hpp"

namespace fsi::materials {

void validate_constants(const MaterialOptions& o) {
  auto fail = [](const char* key, double value, const char* range) {
    throw InputError(std::string("material: ") + key + " = " + std::to_string(value) +
                     ": must be " + range);
  };
  if (!(o.youngs_modulus > 0.0) || !std::isfinite(o.youngs_modulus))
    fail("youngs_modulus", o.youngs_modulus, "> 0");
  if (!(o.poisson_ratio > -1.0 && o.poisson_ratio < 0.5))
    fail("poisson_ratio", o.poisson_ratio, "in (-1, 0.5)");
  if (!(o.density > 0.0) || !std::isfinite(o.density)) fail("density", o.density, "> 0");
}

void validate(const MaterialOptions& o) {
  validate_constants(o);
  if (o.model == MaterialModel::neo_hookean && o.plane != PlaneModel::plane_strain)
    throw InputError("material: neo_hookean is implemented in plane strain only");
}

std::unique_ptr<Material> make_material(const MaterialOptions& o) {
  if (o.model == MaterialModel::neo_hookean) return std::make_unique<NeoHookean>(o);
  return std::make_unique<StVenantKirchhoff>(o);
}

std::unique_ptr<Material3> make_material_3d(const MaterialOptions& o) {
  if (o.model == MaterialModel::neo_hookean) return std::make_unique<NeoHookean3>(o);
  return std::make_unique<StVenantKirchhoff3>(o);
}

double von_mises(const Material& law, const Mat2& F, const Mat2& E) {
  const double J = F.determinant();
  const Mat2 sigma = F * law.stress(E) * F.transpose() / J;
  const double s33 = law.stress_33(E) / J; // F33 = 1
  const double sxx = sigma(0, 0), syy = sigma(1, 1), sxy = sigma(0, 1);
  return std::sqrt(
      0.5 * ((sxx - syy) * (sxx - syy) + (syy - s33) * (syy - s33) + (s33 - sxx) * (s33 - sxx)) +
      3.0 * sxy * sxy);
}

} // namespace fsi::materials
