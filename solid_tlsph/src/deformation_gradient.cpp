// Kinematics: the deformation gradient F_a (eq. 13) from the reference pairs, and det F.
#include <Eigen/LU>
#include <array>

#include "fsi/core/parallel.hpp"
#include "solid_tlsph/solid.hpp"

namespace fsi::tlsph {

template <int D> auto BasicTlsphSolid<D>::deformation_gradient(std::size_t a) const -> Mat {
  // eq. 13: F_a = (sum_b (u_b - u_a) (x) grad0 W_ab V_b) B0_a + I
  const auto x = x_.coords(), X0 = X0_.coords(); // raw arrays: no reloads in the pair loop
  const Vec u_a = displacement(a);
  // The quadratic correction: F_a = I + sum_b (u_b - u_a) (x) g~_ab (the gradients corrected).
  const auto& g = quadratic_ ? pair_q_ : pair_g_;
  std::array<const double*, D> gp;
  for (int j = 0; j < D; ++j) gp[j] = g[j].data();
  Mat G = Mat::Zero();
  for (std::uint32_t p = pair_start_[a]; p < pair_start_[a + 1]; ++p) {
    const std::uint32_t b = pair_b_[p];
    for (int i = 0; i < D; ++i) {
      const double du = x[i][b] - X0[i][b] - u_a(i);
      for (int j = 0; j < D; ++j) G(i, j) += du * gp[j][p];
    }
  }
  if (quadratic_) return G + Mat::Identity();
  Mat F;
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j) {
      double s = i == j ? 1.0 : 0.0; // (G B0)_ij + I_ij, summed as in eq. 13
      for (int k = 0; k < D; ++k) s += G(i, k) * (*B_[D * k + j])[a];
      F(i, j) = s;
    }
  return F;
}

template <int D> std::vector<double> BasicTlsphSolid<D>::det_F() const {
  std::vector<double> out(size());
  parallel_for(size(), [&](std::size_t i) { out[i] = deformation_gradient(i).determinant(); });
  return out;
}

template auto BasicTlsphSolid<2>::deformation_gradient(std::size_t) const -> Mat;
template auto BasicTlsphSolid<3>::deformation_gradient(std::size_t) const -> Mat;
template std::vector<double> BasicTlsphSolid<2>::det_F() const;
template std::vector<double> BasicTlsphSolid<3>::det_F() const;

} // namespace fsi::tlsph
