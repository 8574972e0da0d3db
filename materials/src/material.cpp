#include "materials/material.hpp"

#include <cmath>
#include <string>

#include "fsi/core/error.hpp"

namespace fsi::materials {

void validate(const MaterialOptions& o) {
  auto fail = [](const char* key, double value, const char* range) {
    throw InputError(std::string("material: ") + key + " = " + std::to_string(value) +
                     ": must be " + range);
  };
  if (!(o.youngs_modulus > 0.0) || !std::isfinite(o.youngs_modulus))
    fail("youngs_modulus", o.youngs_modulus, "> 0");
  if (!(o.poisson_ratio > -1.0 && o.poisson_ratio < 0.5))
    fail("poisson_ratio", o.poisson_ratio, "in (-1, 0.5)");
  if (!(o.density > 0.0) || !std::isfinite(o.density)) fail("density", o.density, "> 0");
  if (o.model == MaterialModel::neo_hookean && o.plane != PlaneModel::plane_strain)
    throw InputError("material: neo_hookean is implemented in plane strain only");
}

std::unique_ptr<Material> make_material(const MaterialOptions& o) {
  if (o.model == MaterialModel::neo_hookean) return std::make_unique<NeoHookean>(o);
  return std::make_unique<StVenantKirchhoff>(o);
}

StVenantKirchhoff::StVenantKirchhoff(const MaterialOptions& o)
    : rho_(o.density), plane_strain_(o.plane == PlaneModel::plane_strain) {
  validate(o);
  const double E = o.youngs_modulus, nu = o.poisson_ratio;
  mu_ = E / (2.0 * (1.0 + nu));
  lambda_ = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
  if (!plane_strain_) lambda_ = 2.0 * lambda_ * mu_ / (lambda_ + 2.0 * mu_); // lambda*
}

double StVenantKirchhoff::energy(const Mat2& E) const {
  const double trE = E.trace();
  return 0.5 * lambda_ * trE * trE + mu_ * (E * E).trace(); // eq. 35
}

Mat2 StVenantKirchhoff::stress(const Mat2& E) const {
  return lambda_ * E.trace() * Mat2::Identity() + 2.0 * mu_ * E; // eq. 34 applied to eq. 35
}

Mat3 StVenantKirchhoff::tangent(const Mat2& /*E*/) const {
  Mat3 D;
  D << lambda_ + 2.0 * mu_, lambda_, 0.0, //
      lambda_, lambda_ + 2.0 * mu_, 0.0,  //
      0.0, 0.0, mu_;
  return D;
}

double StVenantKirchhoff::stress_33(const Mat2& E) const {
  return plane_strain_ ? lambda_ * E.trace() : 0.0;
}

NeoHookean::NeoHookean(const MaterialOptions& o) : rho_(o.density) {
  validate(o);
  const double E = o.youngs_modulus, nu = o.poisson_ratio;
  mu_ = E / (2.0 * (1.0 + nu));
  lambda_ = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
}

namespace {
/// C = I + 2 E and ln J = ln det C / 2 (det C = J^2 > 0 for any E of a non-degenerate F).
struct RightCauchyGreen {
  Mat2 C, C_inv;
  double log_J;
  explicit RightCauchyGreen(const Mat2& E)
      : C(Mat2::Identity() + 2.0 * E), C_inv(C.inverse()), log_J(0.5 * std::log(C.determinant())) {}
};
} // namespace

double NeoHookean::energy(const Mat2& E) const {
  const RightCauchyGreen c(E);
  return 0.5 * mu_ * (c.C.trace() - 2.0) - mu_ * c.log_J + 0.5 * lambda_ * c.log_J * c.log_J;
}

Mat2 NeoHookean::stress(const Mat2& E) const {
  const RightCauchyGreen c(E);
  return mu_ * (Mat2::Identity() - c.C_inv) + lambda_ * c.log_J * c.C_inv;
}

Mat3 NeoHookean::tangent(const Mat2& E) const {
  const RightCauchyGreen c(E);
  const double a = c.C_inv(0, 0), b = c.C_inv(1, 1), s = c.C_inv(0, 1);
  const double m = mu_ - lambda_ * c.log_J; // the factor of I_{C^-1}
  Mat3 D;
  D << (lambda_ + 2.0 * m) * a * a, lambda_ * a * b + 2.0 * m * s * s, (lambda_ + 2.0 * m) * a * s,
      lambda_ * a * b + 2.0 * m * s * s, (lambda_ + 2.0 * m) * b * b, (lambda_ + 2.0 * m) * b * s,
      (lambda_ + 2.0 * m) * a * s, (lambda_ + 2.0 * m) * b * s,
      lambda_ * s * s + m * (a * b + s * s);
  return D;
}

double NeoHookean::stress_33(const Mat2& E) const {
  return lambda_ * RightCauchyGreen(E).log_J; // C33 = 1
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
