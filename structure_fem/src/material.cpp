#include "structure_fem/material.hpp"

#include <cmath>
#include <string>

#include "fsi/core/error.hpp"

namespace fsi::fem {

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

} // namespace fsi::fem
