#pragma once
// The MPS weight function. Anything callable as double(double r) with w(r) = 0 for r >= r_e can
// replace it in the wall-weight tables (wall_weight.hpp).

namespace fsi::erp {

/// w(r) = (r/r_e - 1)^2 for 0 <= r < r_e, else 0 (eq. 8).
struct QuadraticWeight {
  double r_e;
  double operator()(double r) const {
    if (r >= r_e) return 0.0;
    const double s = r / r_e - 1.0;
    return s * s;
  }
};

} // namespace fsi::erp
