#pragma once
// Saint Venant–Kirchhoff, W = lambda/2 (tr E)^2 + mu tr(E^2) (eq. 35), S = lambda tr E I + 2 mu E,
// dS/dE = lambda I (x) I + 2 mu II (constant), in D = 2 (plane) and 3. Plane stress replaces
// lambda by lambda* = 2 lambda mu / (lambda + 2 mu).
#include "materials/material.hpp"

namespace fsi::materials {

template <int D> class BasicStVenantKirchhoff : public MaterialInterface<D> {
public:
  explicit BasicStVenantKirchhoff(const MaterialOptions& o) : rho_(o.density) {
    validate_constants(o);
    const double E = o.youngs_modulus, nu = o.poisson_ratio;
    mu_ = E / (2.0 * (1.0 + nu));
    lambda_ = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
  }
  double energy(const MatD<D>& E) const override {
    const double trE = E.trace();
    return 0.5 * lambda_ * trE * trE + mu_ * (E * E).trace(); // eq. 35
  }
  MatD<D> stress(const MatD<D>& E) const override {
    return lambda_ * E.trace() * MatD<D>::Identity() + 2.0 * mu_ * E; // eq. 34 applied to eq. 35
  }
  VoigtMatD<D> tangent(const MatD<D>& /*E*/) const override {
    VoigtMatD<D> C = VoigtMatD<D>::Zero();
    C.template topLeftCorner<D, D>().setConstant(lambda_);
    for (int a = 0; a < D; ++a) C(a, a) = lambda_ + 2.0 * mu_;
    for (int a = D; a < voigt_size<D>; ++a) C(a, a) = mu_; // engineering shear: 2 mu / 2
    return C;
  }
  double density() const override { return rho_; }
  double lambda() const {
    return lambda_;
  } ///< in 2-D the in-plane lambda (lambda* in plane stress)
  double mu() const { return mu_; }

protected:
  double lambda_, mu_, rho_;
};

/// The 2-D law: plane strain or plane stress.
class StVenantKirchhoff final : public BasicStVenantKirchhoff<2> {
public:
  explicit StVenantKirchhoff(const MaterialOptions& o)
      : BasicStVenantKirchhoff<2>(o), plane_strain_(o.plane == PlaneModel::plane_strain) {
    validate(o);
    if (!plane_strain_) lambda_ = 2.0 * lambda_ * mu_ / (lambda_ + 2.0 * mu_); // lambda*
  }
  double stress_33(const Mat2& E) const override {
    return plane_strain_ ? lambda_ * E.trace() : 0.0;
  }

private:
  bool plane_strain_;
};

using StVenantKirchhoff3 = BasicStVenantKirchhoff<3>;

} // namespace fsi::materials
