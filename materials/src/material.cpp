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

double von_mises(const MatD<3>& sigma) {
  const double sxx = sigma(0, 0), syy = sigma(1, 1), szz = sigma(2, 2);
  const double sxy = sigma(0, 1), syz = sigma(1, 2), sxz = sigma(0, 2);
  return std::sqrt(
      0.5 * ((sxx - syy) * (sxx - syy) + (syy - szz) * (syy - szz) + (szz - sxx) * (szz - sxx)) +
      3.0 * sxy * sxy + 3.0 * syz * syz + 3.0 * sxz * sxz);
}

double von_mises(const Material& law, const Mat2& F, const Mat2& E) {
  const double J = F.determinant();
  MatD<3> sigma = MatD<3>::Zero();
  sigma.topLeftCorner<2, 2>() = F * law.stress(E) * F.transpose() / J;
  sigma(2, 2) = law.stress_33(E) / J; // F33 = 1
  return von_mises(sigma);
}

double von_mises(const Material3& law, const MatD<3>& F, const MatD<3>& E) {
  return von_mises(MatD<3>(F * law.stress(E) * F.transpose() / F.determinant()));
}

} // namespace fsi::materials
