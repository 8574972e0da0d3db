// Kernel gradient correction: the matrices B_i of RKGC (eq. 19) with the WKGC weighting
// (eqs. 21-22), and the corrected gradients of a particle field they give.
#include "fluid_sph/sph_fluid.hpp"

#include "fsi/core/parallel.hpp"

#include <algorithm>

namespace fsi::sph {

void SphFluid::correction_matrices() {
  auto& f = fluid_;
  const bool on = options_.correction == Correction::rkgc;
  const double alpha = options_.wkgc_alpha;
  parallel_for(f.size(), [&](std::size_t i) {
    // A_i = -sum_j r_ij (x) grad W_ij V_j = -sum_j r dW e (x) e V_j (eq. 19), symmetric.
    double a00 = 0.0, a01 = 0.0, a11 = 0.0;
    for (std::uint32_t k = pstart_[i]; k < pstart_[i + 1]; ++k) {
      const double s = -pr_[k] * pdw_[k] * f.vol[pj_[k]];
      a00 += s * pex_[k] * pex_[k];
      a01 += s * pex_[k] * pey_[k];
      a11 += s * pey_[k] * pey_[k];
    }
    for (std::uint32_t k = wstart_[i]; k < wstart_[i + 1]; ++k) {
      const double s = -wr_[k] * wdw_[k] * walls_.vol[wj_[k]];
      a00 += s * wex_[k] * wex_[k];
      a01 += s * wex_[k] * wey_[k];
      a11 += s * wey_[k] * wey_[k];
    }
    const double det = a00 * a11 - a01 * a01;
    f.det_a[i] = det;
    if (!on) {
      f.b00[i] = f.b11[i] = 1.0;
      f.b01[i] = 0.0;
      return;
    }
    // B = (A^T A + eps I)^-1 A^T (regularised inverse; A symmetric).
    const double eps = 1e-12;
    const double m00 = a00 * a00 + a01 * a01 + eps, m01 = a00 * a01 + a01 * a11;
    const double m11 = a01 * a01 + a11 * a11 + eps;
    const double inv = 1.0 / (m00 * m11 - m01 * m01);
    const double i00 = m11 * inv, i01 = -m01 * inv, i11 = m00 * inv;
    double b00 = i00 * a00 + i01 * a01, b01 = i00 * a01 + i01 * a11, b11 = i01 * a01 + i11 * a11;
    // WKGC (eqs. 21-22): B~ = w1 B + w2 I, kappa = max(alpha - |A|, 0).
    const double d = std::max(det, 0.0), kappa = std::max(alpha - d, 0.0);
    if (d + kappa <= 0.0) {
      b00 = b11 = 1.0, b01 = 0.0;
    } else {
      const double w1 = d / (d + kappa), w2 = kappa / (d + kappa);
      b00 = w1 * b00 + w2;
      b01 = w1 * b01;
      b11 = w1 * b11 + w2;
    }
    f.b00[i] = b00;
    f.b01[i] = b01;
    f.b11[i] = b11;
  });
}

Vec2 SphFluid::rkgc_gradient(std::size_t i, const std::vector<double>& psi) const {
  const auto& f = fluid_;
  Vec2 g = Vec2::Zero();
  for (std::uint32_t k = pstart_[i]; k < pstart_[i + 1]; ++k) {
    const std::uint32_t j = pj_[k];
    const double dWV = pdw_[k] * f.vol[j], gx = dWV * pex_[k], gy = dWV * pey_[k];
    g.x() += psi[i] * (f.b00[j] * gx + f.b01[j] * gy) + psi[j] * (f.b00[i] * gx + f.b01[i] * gy);
    g.y() += psi[i] * (f.b01[j] * gx + f.b11[j] * gy) + psi[j] * (f.b01[i] * gx + f.b11[i] * gy);
  }
  return g;
}

Vec2 SphFluid::plain_difference_gradient(std::size_t i, const std::vector<double>& psi) const {
  Vec2 g = Vec2::Zero();
  for (std::uint32_t k = pstart_[i]; k < pstart_[i + 1]; ++k) {
    const std::uint32_t j = pj_[k];
    const double s = (psi[j] - psi[i]) * pdw_[k] * fluid_.vol[j];
    g += s * Vec2(pex_[k], pey_[k]);
  }
  return g;
}

Vec2 SphFluid::corrected_difference_gradient(std::size_t i, const std::vector<double>& psi) const {
  const Vec2 g = plain_difference_gradient(i, psi);
  const auto& f = fluid_;
  return Vec2(f.b00[i] * g.x() + f.b01[i] * g.y(), f.b01[i] * g.x() + f.b11[i] * g.y());
}

} // namespace fsi::sph
