// The reference configuration's kernel gradient correction, built once: the neighbour pairs
// within 2h with grad0 W_ab V_b, B0 (eq. 14, GradientCorrection::linear) and the quadratic
// fit's corrected gradients g~_ab (GradientCorrection::quadratic).
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <type_traits>

#include "fsi/core/error.hpp"
#include "particles/cell_grid.hpp"
#include "particles/kernels.hpp"
#include "particles/neighbor_list.hpp"
#include "shared.hpp"
#include "solid_tlsph/solid.hpp"

namespace fsi::tlsph {

namespace {

/// |v| as std::hypot takes it (2-D: the two-argument form of the 2-D code, bitwise).
template <int D> double length(const VecD<D>& v) {
  if constexpr (D == 2)
    return std::hypot(v(0), v(1));
  else
    return std::hypot(v(0), v(1), v(2));
}

} // namespace

template <int D> void BasicTlsphSolid<D>::build_reference() {
  const std::size_t n = size();
  Vec lo = at(X0_, 0), hi = lo;
  for (std::size_t i = 0; i < n; ++i) lo = lo.cwiseMin(at(X0_, i)), hi = hi.cwiseMax(at(X0_, i));
  const particles::BasicWendlandC2<D> kernel(h_);
  const double radius = kernel.cutoff();
  particles::BasicCellGrid<D> grid(lo, hi, radius);
  grid.bin(X0_.coords(), n);
  particles::BasicNeighborList<D> list;
  const auto capacity = static_cast<std::size_t>(options_.max_neighbors);
  if (!list.build(grid, X0_.coords(), n, radius, capacity))
    throw InputError("tlsph: particle " + std::to_string(list.overflow()) + " has more than " +
                     "max_neighbors = " + std::to_string(capacity) + " neighbours within 2h");
  pair_start_.assign(n + 1, 0);
  for (std::size_t a = 0; a < n; ++a) pair_start_[a + 1] = pair_start_[a] + list.count(a);
  const std::size_t pairs = pair_start_[n];
  pair_b_.resize(pairs), pair_dwr_.resize(pairs);
  for (auto& g : pair_g_) g.resize(pairs);
  std::size_t bad = none;
  for (std::size_t a = 0; a < n; ++a) {
    const std::uint32_t* row = list.row(a);
    std::vector<std::uint32_t> sorted(row, row + list.count(a));
    std::sort(sorted.begin(), sorted.end()); // a fixed summation order
    Mat M = Mat::Zero();
    for (std::size_t k = 0; k < sorted.size(); ++k) {
      const std::size_t p = pair_start_[a] + k, b = sorted[k];
      Vec X_ab;
      for (int c = 0; c < D; ++c) X_ab(c) = X0_[c][a] - X0_[c][b];
      const double r = X_ab.norm(), dW = kernel.dW(r);
      const Vec g = X_ab / r * dW * V0_[b]; // grad0 W_ab V_b, gradient with respect to X_a
      pair_b_[p] = static_cast<std::uint32_t>(b);
      for (int c = 0; c < D; ++c) pair_g_[c][p] = g(c);
      pair_dwr_[p] = -dW / r * V0_[b];
      M -= X_ab * g.transpose(); // sum (X_b - X_a) (x) grad0 W_ab V_b (eq. 14)
    }
    Mat B = Mat::Identity();
    if (options_.kernel_correction) {
      const double det = M.determinant();
      if (!(std::abs(det) > 1e-8)) { // M ~ I for a full lattice: det ~ 1
        if (bad == none) bad = a;
      } else {
        B = M.inverse();
      }
    }
    for (int i = 0; i < D; ++i)
      for (int j = 0; j < D; ++j) (*B_[D * i + j])[a] = B(i, j);
  }
  if (bad != none)
    throw InputError("tlsph: particle " + std::to_string(bad) +
                     " has a singular moment matrix (eq. 14): too few neighbours in 2h");
  quadratic_ = options_.gradient_correction == GradientCorrection::quadratic;
  if (quadratic_) build_quadratic();
}

template <int D> void BasicTlsphSolid<D>::build_quadratic() {
  // Weighted least squares of u_b - u_a by c . p(d), d = (X_b - X_a) / h, with the monomials
  // p of d (shared.hpp; 2-D: (d_x, d_y, d_x^2 / 2, d_x d_y, d_y^2 / 2)) and the weights of
  // eq. 14, w_ab = |dW_ab| / r_ab V_b (with p = d alone this is exactly B0: g~_ab = B0_a grad0
  // W_ab V_b). The gradient is (c_0 .. c_{D-1}) / h, so g~_ab = w_ab [A_a^-1 p_ab]_(0..D-1) / h,
  // A_a = sum w p p^T.
  constexpr int M = monomial_count<D>;
  // 3-D: dynamic (gcc's -Wmaybe-uninitialized misfires in Eigen's fixed 9 x 9 rcond); built once.
  using MatM = std::conditional_t<D == 2, Eigen::Matrix<double, M, M>, Eigen::MatrixXd>;
  const std::size_t n = size(), pairs = pair_b_.size();
  for (auto& g : pair_q_) g.resize(pairs);
  pair_rev_.resize(pairs);
  auto pair_monomials = [&](std::size_t a, std::size_t b) {
    Vec d;
    for (int c = 0; c < D; ++c) d(c) = (X0_[c][b] - X0_[c][a]) / h_;
    return monomials<D>(d);
  };
  const bool hourglass = options_.hourglass > 0.0;
  if (hourglass) pair_fit_.assign(M * pairs, 0.0);
  std::size_t bad = none;
  for (std::size_t a = 0; a < n; ++a) {
    MatM A = MatM::Zero(M, M);
    for (std::uint32_t q = pair_start_[a]; q < pair_start_[a + 1]; ++q) {
      const Monomials<D> p = pair_monomials(a, pair_b_[q]);
      A += pair_dwr_[q] * h_ * h_ * p * p.transpose(); // w scaled by h^2: A ~ 1
    }
    const Eigen::PartialPivLU<MatM> lu(A);
    if (!(lu.rcond() > 1e-10)) {
      if (bad == none) bad = a;
      continue;
    }
    for (std::uint32_t q = pair_start_[a]; q < pair_start_[a + 1]; ++q) {
      const Monomials<D> c = lu.solve(pair_monomials(a, pair_b_[q]));
      for (int k = 0; k < D; ++k) pair_q_[k][q] = pair_dwr_[q] * h_ * c(k);
      if (hourglass) // the fit's coefficients are sum_c (u_c - u_a) s_ac^T
        for (int m = 0; m < M; ++m) pair_fit_[M * q + m] = pair_dwr_[q] * h_ * h_ * c(m);
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
      Vec gq, gl; // g~_ab and B0_a grad0 W_ab V_b
      for (int i = 0; i < D; ++i) {
        gq(i) = pair_q_[i][q], gl(i) = 0.0;
        for (int j = 0; j < D; ++j) gl(i) += (*B_[D * i + j])[a] * pair_g_[j][q];
      }
      sq += length(gq), sl += length(gl);
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

template <int D> auto BasicTlsphSolid<D>::correction_matrix(std::size_t a) const -> Mat {
  Mat B;
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j) B(i, j) = (*B_[D * i + j])[a];
  return B;
}

template void BasicTlsphSolid<2>::build_reference();
template void BasicTlsphSolid<3>::build_reference();
template void BasicTlsphSolid<2>::build_quadratic();
template void BasicTlsphSolid<3>::build_quadratic();
template auto BasicTlsphSolid<2>::correction_matrix(std::size_t) const -> Mat;
template auto BasicTlsphSolid<3>::correction_matrix(std::size_t) const -> Mat;

} // namespace fsi::tlsph
