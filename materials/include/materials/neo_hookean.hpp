#pragma once
// Compressible neo-Hookean in plane strain (F33 = 1), with the Lamé constants of E and nu:
//   W = mu/2 (tr C + 1 - 3) - mu ln J + lambda/2 (ln J)^2,   C = I + 2 E,  J = sqrt(det C),
//   S = mu (I - C^-1) + lambda ln J C^-1,
//   dS/dE = lambda C^-1 (x) C^-1 + 2 (mu - lambda ln J) I_{C^-1},
//   with I_{C^-1}_ijkl = (C^-1_ik C^-1_jl + C^-1_il C^-1_jk) / 2 (Bonet & Wood, Nonlinear
// Continuum Mechanics for FEA, sec. 6.4.3). The same as St. Venant–Kirchhoff to first order in E;
// W -> infinity as J -> 0.
#include "materials/material.hpp"

#include <cmath>

namespace fsi::materials {

class NeoHookean final : public Material {
public:
  explicit NeoHookean(const MaterialOptions& o) : rho_(o.density) {
    validate(o);
    const double E = o.youngs_modulus, nu = o.poisson_ratio;
    mu_ = E / (2.0 * (1.0 + nu));
    lambda_ = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
  }
  double energy(const Mat2& E) const override {
    const RightCauchyGreen c(E);
    return 0.5 * mu_ * (c.C.trace() - 2.0) - mu_ * c.log_J + 0.5 * lambda_ * c.log_J * c.log_J;
  }
  Mat2 stress(const Mat2& E) const override {
    const RightCauchyGreen c(E);
    return mu_ * (Mat2::Identity() - c.C_inv) + lambda_ * c.log_J * c.C_inv;
  }
  Mat3 tangent(const Mat2& E) const override {
    const RightCauchyGreen c(E);
    const double a = c.C_inv(0, 0), b = c.C_inv(1, 1), s = c.C_inv(0, 1);
    const double m = mu_ - lambda_ * c.log_J; // the factor of I_{C^-1}
    Mat3 D;
    D << (lambda_ + 2.0 * m) * a * a, lambda_ * a * b + 2.0 * m * s * s,
        (lambda_ + 2.0 * m) * a * s, lambda_ * a * b + 2.0 * m * s * s, (lambda_ + 2.0 * m) * b * b,
        (lambda_ + 2.0 * m) * b * s, (lambda_ + 2.0 * m) * a * s, (lambda_ + 2.0 * m) * b * s,
        lambda_ * s * s + m * (a * b + s * s);
    return D;
  }
  double stress_33(const Mat2& E) const override {
    return lambda_ * RightCauchyGreen(E).log_J; // C33 = 1
  }
  double density() const override { return rho_; }

private:
  /// C = I + 2 E and ln J = ln det C / 2 (det C = J^2 > 0 for any E of a non-degenerate F).
  struct RightCauchyGreen {
    Mat2 C, C_inv;
    double log_J;
    explicit RightCauchyGreen(const Mat2& E)
        : C(Mat2::Identity() + 2.0 * E), C_inv(C.inverse()),
          log_J(0.5 * std::log(C.determinant())) {}
  };
  double lambda_, mu_, rho_;
};

} // namespace fsi::materials
