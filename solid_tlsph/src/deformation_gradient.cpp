// Kinematics: the deformation gradient F_a (eq. 13) from the reference pairs, and det F.
#include <Eigen/LU>

#include "fsi/core/parallel.hpp"
#include "solid_tlsph/solid.hpp"

namespace fsi::tlsph {

Mat2 TlsphSolid::deformation_gradient(std::size_t a) const {
  // eq. 13: F_a = (sum_b (u_b - u_a) (x) grad0 W_ab V_b) B0_a + I
  const double ux_a = x_[a] - X0_[a], uy_a = y_[a] - Y0_[a];
  // The quadratic correction: F_a = I + sum_b (u_b - u_a) (x) g~_ab (the gradients corrected).
  const double* gx = quadratic_ ? pair_qx_.data() : pair_gx_.data();
  const double* gy = quadratic_ ? pair_qy_.data() : pair_gy_.data();
  double G00 = 0.0, G01 = 0.0, G10 = 0.0, G11 = 0.0;
  for (std::uint32_t p = pair_start_[a]; p < pair_start_[a + 1]; ++p) {
    const std::uint32_t b = pair_b_[p];
    const double dux = x_[b] - X0_[b] - ux_a, duy = y_[b] - Y0_[b] - uy_a;
    G00 += dux * gx[p], G01 += dux * gy[p];
    G10 += duy * gx[p], G11 += duy * gy[p];
  }
  if (quadratic_) {
    Mat2 F;
    F << 1.0 + G00, G01, G10, 1.0 + G11;
    return F;
  }
  Mat2 F;
  F(0, 0) = 1.0 + G00 * B00_[a] + G01 * B10_[a];
  F(0, 1) = G00 * B01_[a] + G01 * B11_[a];
  F(1, 0) = G10 * B00_[a] + G11 * B10_[a];
  F(1, 1) = 1.0 + G10 * B01_[a] + G11 * B11_[a];
  return F;
}

std::vector<double> TlsphSolid::det_F() const {
  std::vector<double> out(size());
  parallel_for(size(), [&](std::size_t i) { out[i] = deformation_gradient(i).determinant(); });
  return out;
}

} // namespace fsi::tlsph
