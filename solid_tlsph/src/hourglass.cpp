// Hourglass control of the quadratic correction: the residuals r_ab of a particle's quadratic
// fit, the penalty's strain (TlsphOptions::hourglass, docs/solid_tlsph.md).
#include "shared.hpp"
#include "solid_tlsph/solid.hpp"

namespace fsi::tlsph {

void TlsphSolid::hourglass_residuals(std::size_t a, double* rx, double* ry) const {
  // r_ab = (u_b - u_a) - C_a p_ab with the fit C_a = sum_c (u_c - u_a) s_ac^T
  const std::uint32_t start = pair_start_[a], end = pair_start_[a + 1];
  const double ux_a = x_[a] - X0_[a], uy_a = y_[a] - Y0_[a];
  double cx[5] = {0.0, 0.0, 0.0, 0.0, 0.0}, cy[5] = {0.0, 0.0, 0.0, 0.0, 0.0};
  for (std::uint32_t q = start; q < end; ++q) {
    const std::uint32_t b = pair_b_[q];
    const double dux = x_[b] - X0_[b] - ux_a, duy = y_[b] - Y0_[b] - uy_a;
    for (int m = 0; m < 5; ++m)
      cx[m] += dux * pair_fit_[5 * q + m], cy[m] += duy * pair_fit_[5 * q + m];
  }
  for (std::uint32_t q = start; q < end; ++q) {
    const std::uint32_t b = pair_b_[q];
    const auto p = monomials((X0_[b] - X0_[a]) / h_, (Y0_[b] - Y0_[a]) / h_);
    double fx = 0.0, fy = 0.0;
    for (int m = 0; m < 5; ++m) fx += cx[m] * p(m), fy += cy[m] * p(m);
    rx[q - start] = x_[b] - X0_[b] - ux_a - fx, ry[q - start] = y_[b] - Y0_[b] - uy_a - fy;
  }
}

} // namespace fsi::tlsph
