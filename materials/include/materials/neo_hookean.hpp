#pragma once
// Compressible neo-Hookean in D = 3 and in 2-D plane strain (F33 = 1, so tr C gains C33 = 1),
// with the Lamé constants of E and nu:
//   W = mu/2 (tr C - 3) - mu ln J + lambda/2 (ln J)^2,   C = I + 2 E,  J = sqrt(det C),
//   S = mu (I - C^-1) + lambda ln J C^-1,
//   dS/dE = lambda C^-1 (x) C^-1 + 2 (mu - lambda ln J) I_{C^-1},
//   with I_{C^-1}_ijkl = (C^-1_ik C^-1_jl + C^-1_il C^-1_jk) / 2 (Bonet & Wood, Nonlinear
// Continuum Mechanics for FEA, sec. 6.4.3). The same as St. Venant–Kirchhoff to first order in E;
// W -> infinity as J -> 0.
#include "materials/material.hpp"

#include <cmath>

namespace fsi::materials {

template <int D> class BasicNeoHookean : public MaterialInterface<D> {
public:
  explicit BasicNeoHookean(const MaterialOptions& o) : rho_(o.density) {
    validate_constants(o);
    const double E = o.youngs_modulus, nu = o.poisson_ratio;
    mu_ = E / (2.0 * (1.0 + nu));
    lambda_ = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
  }
  double energy(const MatD<D>& E) const override {
    const RightCauchyGreen c(E); // tr C - 3 is tr C - D in 2-D plane strain (C33 = 1)
    return 0.5 * mu_ * (c.C.trace() - D) - mu_ * c.log_J + 0.5 * lambda_ * c.log_J * c.log_J;
  }
  MatD<D> stress(const MatD<D>& E) const override {
    const RightCauchyGreen c(E);
    return mu_ * (MatD<D>::Identity() - c.C_inv) + lambda_ * c.log_J * c.C_inv;
  }
  VoigtMatD<D> tangent(const MatD<D>& E) const override {
    const RightCauchyGreen c(E);
    const double m = mu_ - lambda_ * c.log_J; // the factor of I_{C^-1}
    VoigtMatD<D> C;
    if constexpr (D == 2) { // the 2-D entries factored by hand (2-D results as before)
      const double a = c.C_inv(0, 0), b = c.C_inv(1, 1), s = c.C_inv(0, 1);
      C << (lambda_ + 2.0 * m) * a * a, lambda_ * a * b + 2.0 * m * s * s,
          (lambda_ + 2.0 * m) * a * s, lambda_ * a * b + 2.0 * m * s * s,
          (lambda_ + 2.0 * m) * b * b, (lambda_ + 2.0 * m) * b * s, (lambda_ + 2.0 * m) * a * s,
          (lambda_ + 2.0 * m) * b * s, lambda_ * s * s + m * (a * b + s * s);
    } else {
      const auto& Ci = c.C_inv;
      for (int r = 0; r < voigt_size<D>; ++r)
        for (int t = 0; t < voigt_size<D>; ++t) {
          const auto [i, j] = voigt_pairs<D>[static_cast<std::size_t>(r)];
          const auto [k, l] = voigt_pairs<D>[static_cast<std::size_t>(t)];
          C(r, t) = lambda_ * Ci(i, j) * Ci(k, l) + m * (Ci(i, k) * Ci(j, l) + Ci(i, l) * Ci(j, k));
        }
    }
    return C;
  }
  double density() const override { return rho_; }

protected:
  /// C = I + 2 E and ln J = ln det C / 2 (det C = J^2 > 0 for any E of a non-degenerate F).
  struct RightCauchyGreen {
    MatD<D> C, C_inv;
    double log_J;
    explicit RightCauchyGreen(const MatD<D>& E)
        : C(MatD<D>::Identity() + 2.0 * E), C_inv(C.inverse()),
          log_J(0.5 * std::log(C.determinant())) {}
  };
  double lambda_, mu_, rho_;
};

/// The 2-D law, plane strain only.
class NeoHookean final : public BasicNeoHookean<2> {
public:
  explicit NeoHookean(const MaterialOptions& o) : BasicNeoHookean<2>(o) { validate(o); }
  double stress_33(const Mat2& E) const override {
    return lambda_ * RightCauchyGreen(E).log_J; // C33 = 1
  }
};

using NeoHookean3 = BasicNeoHookean<3>;

} // namespace fsi::materials
