#pragma once
// Smoothing kernels of the particle solvers, each in one place.
//   MpsWeight         the MPS weight function of the EMPS fluid and the ERP wall tables (EMPS
//   paper,
//                     eq. 8); it does not depend on the dimension.
//   BasicWendlandC2<D> the Wendland C2 kernel of the SPH fluid and the TL-SPH solid in D = 2 or 3
//                     dimensions (RKGC paper, eq. 4; ../shared/sph-method-notes.md, "Kernel and
//                     resolution"); WendlandC2 is the 2-D one.
#include <numbers>

namespace fsi::particles {

/// w(r) = (1 - r/r_e)^2 for 0 <= r < r_e, else 0 (eq. 8). Anything callable as double(double r)
/// with w(r) = 0 for r >= r_e can replace it in the wall-weight tables
/// (geometry_erp/wall_weight.hpp).
struct MpsWeight {
  double r_e, inv_re;
  explicit MpsWeight(double radius) : r_e(radius), inv_re(1.0 / radius) {}
  /// For r already known to be below r_e (the pair loops test r^2 < r_e^2 first).
  double inside(double r) const {
    const double s = 1.0 - r * inv_re;
    return s * s;
  }
  double operator()(double r) const { return r < r_e ? inside(r) : 0.0; }
};

/// Wendland C2 in D = 2 or 3 dimensions with smoothing length h, support 2h, q = r/h:
///   W(q) = sigma_D (1 - q/2)^4 (1 + 2q),   dW/dr = sigma_D / h * 0.625 q (q - 2)^3 (<= 0),
///   sigma_2 = 7 / (4 pi h^2),   sigma_3 = 21 / (16 pi h^3)
/// (each normalises W to integrate to 1 over R^D; 0.625 = 5/8: d/dq [(1 - q/2)^4 (1 + 2q)] =
/// -5 q (1 - q/2)^3 = (5/8) q (q - 2)^3).
template <int D> struct BasicWendlandC2 {
  static_assert(D == 2 || D == 3, "Wendland C2 is normalised for D = 2 and D = 3");
  double h, inv_h, factor_w, factor_dw;
  explicit BasicWendlandC2(double smoothing_length)
      : h(smoothing_length), inv_h(1.0 / smoothing_length), factor_w(sigma(smoothing_length)),
        factor_dw(factor_w * inv_h * 0.625) {}
  /// sigma_D of the comment above.
  static double sigma(double h) {
    if constexpr (D == 2)
      return 7.0 / (4.0 * std::numbers::pi * h * h);
    else
      return 21.0 / (16.0 * std::numbers::pi * h * h * h);
  }
  double cutoff() const { return 2.0 * h; }
  double W(double r) const {
    const double q = r * inv_h;
    if (q >= 2.0) return 0.0;
    const double s = 1.0 - 0.5 * q;
    return factor_w * s * s * s * s * (1.0 + 2.0 * q);
  }
  /// dW/dr (<= 0); zero at r = 0 and beyond the support.
  double dW(double r) const {
    const double q = r * inv_h;
    if (q >= 2.0) return 0.0;
    const double s = q - 2.0;
    return factor_dw * q * s * s * s;
  }
};

/// The 2-D kernel of the 2-D solvers.
using WendlandC2 = BasicWendlandC2<2>;

} // namespace fsi::particles
