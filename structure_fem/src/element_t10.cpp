#include "structure_fem/element_t10.hpp"

#include <algorithm>
#include <limits>

#include "reference_map.hpp"
#include "structure_fem/shape_t10.hpp"

namespace fsi::fem {

namespace {

using Mat310 = Eigen::Matrix<double, 3, 10>;
using Vec6 = Eigen::Matrix<double, 6, 1>;

} // namespace

double t10_min_jacobian(const TetNodes& X) {
  const auto C = node_coordinates(X);
  double m = std::numeric_limits<double>::infinity();
  auto at = [&](double xi, double eta, double zeta) {
    m = std::min(m, jacobian(t10_shape_derivatives(xi, eta, zeta), C).determinant());
  };
  for (const auto& p : t10_node_parent) at(p[0], p[1], p[2]);
  for (const auto& q : tet_rule_degree2) at(q.xi, q.eta, q.zeta);
  for (const auto& q : tet_rule_degree5) at(q.xi, q.eta, q.zeta);
  return m;
}

double t10_volume(const TetNodes& X) {
  const auto C = node_coordinates(X);
  double volume = 0.0;
  for (const auto& q : tet_rule_degree5)
    volume += q.weight * jacobian(t10_shape_derivatives(q.xi, q.eta, q.zeta), C).determinant();
  return volume;
}

ElementT10::ElementT10(const TetNodes& X) {
  const auto C = node_coordinates(X);
  for (std::size_t q = 0; q < tet_rule_degree2.size(); ++q) {
    const auto& p = tet_rule_degree2[q];
    const Mat310 dN = t10_shape_derivatives(p.xi, p.eta, p.zeta);
    const Mat3 J = jacobian(dN, C);
    dNdX_[q] = J.inverse() * dN;
    w_detJ_[q] = p.weight * J.determinant();
  }
}

// Total-Lagrangian forms (Bonet & Wood, Nonlinear Continuum Mechanics for Finite Element
// Analysis, 2nd ed., ch. 9): with H = grad_0 u = sum_K u_K (x) grad_0 N_K, F = I + H and the
// Green–Lagrange strain E = (H + H^T + H^T H) / 2 (eq. 36 of the 2-D paper, no cancellation at
// small strain),
//   internal force  T_K = integral F S grad_0 N_K dV                      (= B^T S in Voigt form)
//   tangent         K_KL = integral [B_K^T C B_L + (grad_0 N_K . S grad_0 N_L) I] dV
// (constitutive and initial-stress parts), where B maps the nodal variations to the Voigt strain
// variation (dE_11, dE_22, dE_33, 2 dE_23, 2 dE_13, 2 dE_12): dE = sym(F^T grad_0 du).
double ElementT10::internal_force(const Vec30& u, const Material3& material, Vec30& f,
                                  Mat30* K) const {
  f.setZero();
  if (K) K->setZero();
  double detF_min = std::numeric_limits<double>::infinity();
  const auto U = Eigen::Map<const Mat310>(u.data()); // column K = u_K
  Eigen::Matrix<double, 6, 30> B;
  for (std::size_t q = 0; q < dNdX_.size(); ++q) {
    const Mat310& dN = dNdX_[q];
    const Mat3 H = U * dN.transpose();
    const Mat3 F = Mat3::Identity() + H;
    detF_min = std::min(detF_min, F.determinant());
    const Mat3 E = 0.5 * (H + H.transpose() + H.transpose() * H);
    const Mat3 S = material.stress(E);
    Vec6 S_voigt;
    for (int r = 0; r < 6; ++r) {
      const auto [i, j] = materials::voigt_pairs<3>[static_cast<std::size_t>(r)];
      S_voigt(r) = S(i, j);
      for (int a = 0; a < 10; ++a)
        for (int k = 0; k < 3; ++k)
          B(r, 3 * a + k) = i == j ? F(k, i) * dN(i, a) : F(k, i) * dN(j, a) + F(k, j) * dN(i, a);
    }
    f.noalias() += w_detJ_[q] * (B.transpose() * S_voigt);
    if (!K) continue;
    K->noalias() += w_detJ_[q] * (B.transpose() * material.tangent(E) * B); // constitutive
    const Eigen::Matrix<double, 10, 10> G = dN.transpose() * S * dN;        // initial stress
    for (int a = 0; a < 10; ++a)
      for (int b = 0; b < 10; ++b)
        for (int k = 0; k < 3; ++k) (*K)(3 * a + k, 3 * b + k) += w_detJ_[q] * G(a, b);
  }
  return detF_min;
}

double ElementT10::strain_energy(const Vec30& u, const Material3& material) const {
  const auto U = Eigen::Map<const Mat310>(u.data());
  double W = 0.0;
  for (std::size_t q = 0; q < dNdX_.size(); ++q) {
    const Mat3 H = U * dNdX_[q].transpose();
    W += w_detJ_[q] * material.energy(0.5 * (H + H.transpose() + H.transpose() * H));
  }
  return W;
}

Mat30 t10_mass(const TetNodes& X, double rho) {
  const auto C = node_coordinates(X);
  Eigen::Matrix<double, 10, 10> m = Eigen::Matrix<double, 10, 10>::Zero();
  for (const auto& q : tet_rule_degree5) {
    const auto N = t10_shape(q.xi, q.eta, q.zeta);
    const double detJ = jacobian(t10_shape_derivatives(q.xi, q.eta, q.zeta), C).determinant();
    m.noalias() += rho * q.weight * detJ * (N * N.transpose());
  }
  Mat30 M = Mat30::Zero();
  for (int a = 0; a < 10; ++a)
    for (int b = 0; b < 10; ++b)
      for (int k = 0; k < 3; ++k) M(3 * a + k, 3 * b + k) = m(a, b);
  return M;
}

std::array<double, 10> t10_nodal_von_mises(const TetNodes& X, const Vec30& u,
                                           const Material3& material) {
  const auto C = node_coordinates(X);
  const auto U = Eigen::Map<const Mat310>(u.data());
  std::array<double, 10> vm{};
  for (std::size_t k = 0; k < 10; ++k) {
    const auto& p = t10_node_parent[k];
    const Mat310 dN = t10_shape_derivatives(p[0], p[1], p[2]);
    const Mat3 H = U * (jacobian(dN, C).inverse() * dN).transpose();
    vm[k] = materials::von_mises(material, Mat3::Identity() + H,
                                 0.5 * (H + H.transpose() + H.transpose() * H));
  }
  return vm;
}

} // namespace fsi::fem
