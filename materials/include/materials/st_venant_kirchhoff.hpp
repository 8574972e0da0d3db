#pragma once
// Saint Venant–Kirchhoff, W = lambda/2 (tr E)^2 + mu tr(E^2) (eq. 35). Plane stress replaces
// lambda by lambda* = 2 lambda mu / (lambda + 2 mu).
#include "materials/material.hpp"

namespace fsi::materials {

class StVenantKirchhoff final : public Material {
public:
  explicit StVenantKirchhoff(const MaterialOptions& o)
      : rho_(o.density), plane_strain_(o.plane == PlaneModel::plane_strain) {
    validate(o);
    const double E = o.youngs_modulus, nu = o.poisson_ratio;
    mu_ = E / (2.0 * (1.0 + nu));
    lambda_ = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
    if (!plane_strain_) lambda_ = 2.0 * lambda_ * mu_ / (lambda_ + 2.0 * mu_); // lambda*
  }
  double energy(const Mat2& E) const override {
    const double trE = E.trace();
    return 0.5 * lambda_ * trE * trE + mu_ * (E * E).trace(); // eq. 35
  }
  Mat2 stress(const Mat2& E) const override {
    return lambda_ * E.trace() * Mat2::Identity() + 2.0 * mu_ * E; // eq. 34 applied to eq. 35
  }
  Mat3 tangent(const Mat2& /*E*/) const override {
    Mat3 D;
    D << lambda_ + 2.0 * mu_, lambda_, 0.0, //
        lambda_, lambda_ + 2.0 * mu_, 0.0,  //
        0.0, 0.0, mu_;
    return D;
  }
  double stress_33(const Mat2& E) const override {
    return plane_strain_ ? lambda_ * E.trace() : 0.0;
  }
  double density() const override { return rho_; }
  double lambda() const { return lambda_; } ///< the in-plane lambda (lambda* in plane stress)
  double mu() const { return mu_; }

private:
  double lambda_, mu_, rho_;
  bool plane_strain_;
};

} // namespace fsi::materials
