// The reference configuration's kernel gradient correction, built once: the neighbour pairs
// within 2h with grad0 W_ab V_b, B0 (eq. 14, GradientCorrection::linear) and the quadratic
// fit's corrected gradients g~_ab (GradientCorrection::quadratic).
#include <Eigen/LU>
#include <algorithm>
#include <cmath>

#include "fsi/core/error.hpp"
#include "particles/cell_grid.hpp"
#include "particles/kernels.hpp"
#include "particles/neighbor_list.hpp"
#include "shared.hpp"
#include "solid_tlsph/solid.hpp"

namespace fsi::tlsph {

void TlsphSolid::build_reference() {
  const std::size_t n = size();
  Vec2 lo(X0_[0], Y0_[0]), hi = lo;
  for (std::size_t i = 0; i < n; ++i)
    lo = lo.cwiseMin(Vec2(X0_[i], Y0_[i])), hi = hi.cwiseMax(Vec2(X0_[i], Y0_[i]));
  const particles::WendlandC2 kernel(h_);
  const double radius = kernel.cutoff();
  particles::CellGrid grid(lo, hi, radius);
  grid.bin(X0_.data(), Y0_.data(), n);
  particles::NeighborList list;
  const auto capacity = static_cast<std::size_t>(options_.max_neighbors);
  if (!list.build(grid, X0_.data(), Y0_.data(), n, radius, capacity))
    throw InputError("tlsph: particle " + std::to_string(list.overflow()) + " has more than " +
                     "max_neighbors = " + std::to_string(capacity) + " neighbours within 2h");
  pair_start_.assign(n + 1, 0);
  for (std::size_t a = 0; a < n; ++a) pair_start_[a + 1] = pair_start_[a] + list.count(a);
  const std::size_t pairs = pair_start_[n];
  pair_b_.resize(pairs), pair_gx_.resize(pairs), pair_gy_.resize(pairs), pair_dwr_.resize(pairs);
  std::size_t bad = none;
  for (std::size_t a = 0; a < n; ++a) {
    const std::uint32_t* row = list.row(a);
    std::vector<std::uint32_t> sorted(row, row + list.count(a));
    std::sort(sorted.begin(), sorted.end()); // a fixed summation order
    Mat2 M = Mat2::Zero();
    for (std::size_t k = 0; k < sorted.size(); ++k) {
      const std::size_t p = pair_start_[a] + k, b = sorted[k];
      const Vec2 X_ab(X0_[a] - X0_[b], Y0_[a] - Y0_[b]);
      const double r = X_ab.norm(), dW = kernel.dW(r);
      const Vec2 g = X_ab / r * dW * V0_[b]; // grad0 W_ab V_b, gradient with respect to X_a
      pair_b_[p] = static_cast<std::uint32_t>(b);
      pair_gx_[p] = g.x(), pair_gy_[p] = g.y();
      pair_dwr_[p] = -dW / r * V0_[b];
      M -= X_ab * g.transpose(); // sum (X_b - X_a) (x) grad0 W_ab V_b (eq. 14)
    }
    Mat2 B = Mat2::Identity();
    if (options_.kernel_correction) {
      const double det = M.determinant();
      if (!(std::abs(det) > 1e-8)) { // M ~ I for a full lattice: det ~ 1
        if (bad == none) bad = a;
      } else {
        B = M.inverse();
      }
    }
    B00_[a] = B(0, 0), B01_[a] = B(0, 1), B10_[a] = B(1, 0), B11_[a] = B(1, 1);
  }
  if (bad != none)
    throw InputError("tlsph: particle " + std::to_string(bad) +
                     " has a singular moment matrix (eq. 14): too few neighbours in 2h");
  quadratic_ = options_.gradient_correction == GradientCorrection::quadratic;
  if (quadratic_) build_quadratic();
}

void TlsphSolid::build_quadratic() {
  // Weighted least squares of u_b - u_a by c . p(d), d = (X_b - X_a) / h, with the monomials
  // p = (d_x, d_y, d_x^2 / 2, d_x d_y, d_y^2 / 2) and the weights of eq. 14, w_ab = |dW_ab| /
  // r_ab V_b (with p = (d_x, d_y) alone this is exactly B0: g~_ab = B0_a grad0 W_ab V_b). The
  // gradient is (c_0, c_1) / h, so g~_ab = w_ab [A_a^-1 p_ab]_(0,1) / h, A_a = sum w p p^T.
  using Vec5 = Eigen::Matrix<double, 5, 1>;
  using Mat5 = Eigen::Matrix<double, 5, 5>;
  const std::size_t n = size(), pairs = pair_b_.size();
  pair_qx_.resize(pairs), pair_qy_.resize(pairs), pair_rev_.resize(pairs);
  auto pair_monomials = [&](std::size_t a, std::size_t b) {
    return monomials((X0_[b] - X0_[a]) / h_, (Y0_[b] - Y0_[a]) / h_);
  };
  const bool hourglass = options_.hourglass > 0.0;
  if (hourglass) pair_fit_.assign(5 * pairs, 0.0);
  std::size_t bad = none;
  for (std::size_t a = 0; a < n; ++a) {
    Mat5 A = Mat5::Zero();
    for (std::uint32_t q = pair_start_[a]; q < pair_start_[a + 1]; ++q) {
      const Vec5 p = pair_monomials(a, pair_b_[q]);
      A += pair_dwr_[q] * h_ * h_ * p * p.transpose(); // w scaled by h^2: A ~ 1
    }
    const Eigen::PartialPivLU<Mat5> lu(A);
    if (!(lu.rcond() > 1e-10)) {
      if (bad == none) bad = a;
      continue;
    }
    for (std::uint32_t q = pair_start_[a]; q < pair_start_[a + 1]; ++q) {
      const Vec5 c = lu.solve(pair_monomials(a, pair_b_[q]));
      pair_qx_[q] = pair_dwr_[q] * h_ * c(0), pair_qy_[q] = pair_dwr_[q] * h_ * c(1);
      if (hourglass) // the fit's coefficients are sum_c (u_c - u_a) s_ac^T
        for (int m = 0; m < 5; ++m) pair_fit_[5 * q + m] = pair_dwr_[q] * h_ * h_ * c(m);
    }
  }
  if (bad != none)
    throw InputError("tlsph: particle " + std::to_string(bad) +
                     " has a singular quadratic moment matrix: too few neighbours in 2h for "
                     "gradient_correction = quadratic");
  // The one-sided quadratic stencils of surface and corner particles have larger weights than
  // B0's, and the highest frequency grows with them: the stable step is divided by the ratio
  // of the largest sum_b |g~_ab| to the largest sum_b |B0_a grad0 W_ab V_b|.
  double sum_q = 0.0, sum_l = 0.0;
  for (std::size_t a = 0; a < n; ++a) {
    double sq = 0.0, sl = 0.0;
    for (std::uint32_t q = pair_start_[a]; q < pair_start_[a + 1]; ++q) {
      sq += std::hypot(pair_qx_[q], pair_qy_[q]);
      sl += std::hypot(B00_[a] * pair_gx_[q] + B01_[a] * pair_gy_[q],
                       B10_[a] * pair_gx_[q] + B11_[a] * pair_gy_[q]);
    }
    sum_q = std::max(sum_q, sq), sum_l = std::max(sum_l, sl);
  }
  dt_scale_ = std::min(1.0, sum_l / sum_q);
  // The reverse pair (b, a) in b's row (rows are sorted by neighbour, the list is symmetric).
  for (std::size_t a = 0; a < n; ++a)
    for (std::uint32_t q = pair_start_[a]; q < pair_start_[a + 1]; ++q) {
      const std::uint32_t b = pair_b_[q];
      const auto first = pair_b_.begin() + pair_start_[b],
                 last = pair_b_.begin() + pair_start_[b + 1];
      const auto it = std::lower_bound(first, last, static_cast<std::uint32_t>(a));
      if (it == last || *it != a)
        throw InputError("tlsph: the reference neighbour list is not symmetric at particle " +
                         std::to_string(a)); // cannot happen with one radius
      pair_rev_[q] = static_cast<std::uint32_t>(it - pair_b_.begin());
    }
}

Mat2 TlsphSolid::correction_matrix(std::size_t a) const {
  Mat2 B;
  B << B00_[a], B01_[a], B10_[a], B11_[a];
  return B;
}

} // namespace fsi::tlsph
