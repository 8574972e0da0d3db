// Kernel gradient correction: the matrices B_i of RKGC (eq. 19) with the WKGC weighting
// (eqs. 21-22), and the corrected gradients of a particle field they give.
#include "fluid_sph/sph_fluid.hpp"

#include "shared.hpp"

#include "fsi/core/parallel.hpp"

#include <Eigen/LU>
#include <algorithm>

namespace fsi::sph {

namespace {

/// B = (A^T A + eps I)^-1 A^T, the regularised inverse of the symmetric A (upper triangle, sym);
/// 2-D in closed form (the 2-D code's arithmetic).
template <int D> void regularised_inverse(const double* A, double* B) {
  const double eps = 1e-12;
  if constexpr (D == 2) {
    const double a00 = A[0], a01 = A[1], a11 = A[2];
    const double m00 = a00 * a00 + a01 * a01 + eps, m01 = a00 * a01 + a01 * a11;
    const double m11 = a01 * a01 + a11 * a11 + eps;
    const double inv = 1.0 / (m00 * m11 - m01 * m01);
    const double i00 = m11 * inv, i01 = -m01 * inv, i11 = m00 * inv;
    B[0] = i00 * a00 + i01 * a01, B[1] = i00 * a01 + i01 * a11, B[2] = i01 * a01 + i11 * a11;
  } else {
    MatD<D> a;
    for (int r = 0; r < D; ++r)
      for (int c = 0; c < D; ++c) a(r, c) = A[sym<D>(r, c)];
    const MatD<D> b = (a * a + eps * MatD<D>::Identity()).inverse() * a;
    for (int r = 0; r < D; ++r) // symmetric up to round-off: the mean of the two triangles
      for (int c = r; c < D; ++c) B[sym<D>(r, c)] = 0.5 * (b(r, c) + b(c, r));
  }
}

} // namespace

template <int D> void BasicSphFluid<D>::correction_matrices() {
  auto& f = fluid_;
  const bool on = options_.correction == Correction::rkgc;
  const double alpha = options_.wkgc_alpha;
  std::array<const double*, D> e, we;
  for (int c = 0; c < D; ++c) e[c] = pe_[c].data(), we[c] = we_[c].data();
  std::array<double*, S> b;
  for (int s = 0; s < S; ++s) b[s] = f.b[s]->data();
  const std::uint32_t *pstart = pstart_.data(), *pj = pj_.data();
  const std::uint32_t *wstart = wstart_.data(), *wj = wj_.data();
  const double *pdw = pdw_.data(), *pr = pr_.data(), *wdw = wdw_.data(), *wr = wr_.data();
  const double *vol = f.vol.data(), *wvol = walls_.vol.data();
  double* det_a = f.det_a.data();
  // Everything by value: the loop reads no member through this and no array through a reference.
  parallel_for(owned(), [=](std::size_t i) {
    // A_i = -sum_j r_ij (x) grad W_ij V_j = -sum_j r dW e (x) e V_j (eq. 19), symmetric.
    double A[S] = {};
    for (std::uint32_t k = pstart[i]; k < pstart[i + 1]; ++k) {
      const double s = -pr[k] * pdw[k] * vol[pj[k]];
      FSI_UNROLL for (int r = 0; r < D; ++r) {
        FSI_UNROLL for (int c = r; c < D; ++c) A[sym<D>(r, c)] += s * e[r][k] * e[c][k];
      }
    }
    for (std::uint32_t k = wstart[i]; k < wstart[i + 1]; ++k) {
      const double s = -wr[k] * wdw[k] * wvol[wj[k]];
      FSI_UNROLL for (int r = 0; r < D; ++r) {
        FSI_UNROLL for (int c = r; c < D; ++c) A[sym<D>(r, c)] += s * we[r][k] * we[c][k];
      }
    }
    double det;
    if constexpr (D == 2) {
      det = A[0] * A[2] - A[1] * A[1];
    } else {
      MatD<D> a;
      FSI_UNROLL for (int r = 0; r < D; ++r) {
        FSI_UNROLL for (int c = 0; c < D; ++c) a(r, c) = A[sym<D>(r, c)];
      }
      det = a.determinant();
    }
    det_a[i] = det;
    double B[S];
    FSI_UNROLL for (int s = 0; s < S; ++s) B[s] = 0.0;
    FSI_UNROLL for (int c = 0; c < D; ++c) B[sym<D>(c, c)] = 1.0;
    if (on) {
      double Binv[S];
      regularised_inverse<D>(A, Binv);
      // WKGC (eqs. 21-22): B~ = w1 B + w2 I, kappa = max(alpha - |A|, 0).
      const double d = std::max(det, 0.0), kappa = std::max(alpha - d, 0.0);
      if (!(d + kappa <= 0.0)) { // else B = I
        const double w1 = d / (d + kappa), w2 = kappa / (d + kappa);
        FSI_UNROLL for (int r = 0; r < D; ++r) {
          FSI_UNROLL for (int c = r; c < D; ++c) B[sym<D>(r, c)] =
              r == c ? w1 * Binv[sym<D>(r, c)] + w2 : w1 * Binv[sym<D>(r, c)];
        }
      }
    }
    FSI_UNROLL for (int s = 0; s < S; ++s) b[s][i] = B[s];
  });
}

template <int D>
auto BasicSphFluid<D>::rkgc_gradient(std::size_t i, const std::vector<double>& psi) const -> Vec {
  const auto& f = fluid_;
  double b_i[S];
  FSI_UNROLL for (int s = 0; s < S; ++s) b_i[s] = (*f.b[s])[i];
  Vec g = Vec::Zero();
  for (std::uint32_t k = pstart_[i]; k < pstart_[i + 1]; ++k) {
    const std::uint32_t j = pj_[k];
    const double dWV = pdw_[k] * f.vol[j];
    double gk[D], b_j[S];
    FSI_UNROLL for (int c = 0; c < D; ++c) gk[c] = dWV * pe_[c][k];
    FSI_UNROLL for (int s = 0; s < S; ++s) b_j[s] = (*f.b[s])[j];
    FSI_UNROLL for (int c = 0; c < D; ++c) g[c] +=
        psi[i] * sym_row<D>(b_j, c, gk) + psi[j] * sym_row<D>(b_i, c, gk);
  }
  return g;
}

template <int D>
auto BasicSphFluid<D>::plain_difference_gradient(std::size_t i,
                                                 const std::vector<double>& psi) const -> Vec {
  Vec g = Vec::Zero();
  for (std::uint32_t k = pstart_[i]; k < pstart_[i + 1]; ++k) {
    const std::uint32_t j = pj_[k];
    const double s = (psi[j] - psi[i]) * pdw_[k] * fluid_.vol[j];
    Vec e;
    FSI_UNROLL for (int c = 0; c < D; ++c) e[c] = pe_[c][k];
    g += s * e;
  }
  return g;
}

template <int D>
auto BasicSphFluid<D>::corrected_difference_gradient(std::size_t i,
                                                     const std::vector<double>& psi) const -> Vec {
  const Vec g = plain_difference_gradient(i, psi);
  double b_i[S];
  FSI_UNROLL for (int s = 0; s < S; ++s) b_i[s] = (*fluid_.b[s])[i];
  Vec out;
  FSI_UNROLL for (int c = 0; c < D; ++c) out[c] = sym_row<D>(b_i, c, g);
  return out;
}

template void BasicSphFluid<2>::correction_matrices();
template void BasicSphFluid<3>::correction_matrices();
template auto BasicSphFluid<2>::rkgc_gradient(std::size_t, const std::vector<double>&) const -> Vec;
template auto BasicSphFluid<3>::rkgc_gradient(std::size_t, const std::vector<double>&) const -> Vec;
template auto BasicSphFluid<2>::plain_difference_gradient(std::size_t,
                                                          const std::vector<double>&) const -> Vec;
template auto BasicSphFluid<3>::plain_difference_gradient(std::size_t,
                                                          const std::vector<double>&) const -> Vec;
template auto BasicSphFluid<2>::corrected_difference_gradient(std::size_t,
                                                              const std::vector<double>&) const
    -> Vec;
template auto BasicSphFluid<3>::corrected_difference_gradient(std::size_t,
                                                              const std::vector<double>&) const
    -> Vec;

} // namespace fsi::sph
