#include "structure_fem/element_t6.hpp"

#include <algorithm>
#include <limits>

#include "reference_map.hpp"
#include "structure_fem/shape_t6.hpp"

namespace fsi::fem {

namespace {

using Mat26 = Eigen::Matrix<double, 2, 6>;

/// H = grad_X u; u as 2 x 6 (column K = u_K). F = I + H (eq. 30 with eq. 28).
Mat2 displacement_gradient(const Mat26& dNdX, const Vec12& u) {
  const auto U = Eigen::Map<const Mat26>(u.data());
  return U * dNdX.transpose();
}

/// Green–Lagrange strain in H as in eq. (36), E = (H + H^T + H^T H) / 2, which avoids the
/// cancellation of (F^T F - I) / 2 at small strain.
Mat2 green_lagrange(const Mat2& H) {
  return 0.5 * (H + H.transpose() + H.transpose() * H);
}

} // namespace

double t6_min_jacobian(const ElementNodes& X) {
  const auto C = node_coordinates(X);
  double detmin = std::numeric_limits<double>::infinity();
  auto at = [&](double xi, double eta) {
    detmin = std::min(detmin, jacobian(t6_shape_derivatives(xi, eta), C).determinant());
  };
  for (const auto& p : t6_node_parent) at(p[0], p[1]);
  for (const auto& q : rule_degree2) at(q.xi, q.eta);
  for (const auto& q : rule_degree4) at(q.xi, q.eta);
  return detmin;
}

double t6_area(const ElementNodes& X) {
  const auto C = node_coordinates(X);
  double area = 0.0;
  for (const auto& q : rule_degree2)
    area += q.weight * jacobian(t6_shape_derivatives(q.xi, q.eta), C).determinant();
  return area;
}

ElementT6::ElementT6(const ElementNodes& X) {
  const auto C = node_coordinates(X);
  for (std::size_t q = 0; q < rule_degree2.size(); ++q) {
    const Mat26 dN = t6_shape_derivatives(rule_degree2[q].xi, rule_degree2[q].eta);
    const Mat2 J = jacobian(dN, C);
    dNdX_[q] = J.inverse() * dN;
    w_detJ_[q] = rule_degree2[q].weight * J.determinant();
  }
}

double ElementT6::internal_force(const Vec12& u, const Material& material, Vec12& f,
                                 Mat12* K) const {
  f.setZero();
  if (K) K->setZero();
  double detF_min = std::numeric_limits<double>::infinity();
  Eigen::Matrix<double, 3, 12> B;
  for (std::size_t q = 0; q < dNdX_.size(); ++q) {
    const Mat26& dN = dNdX_[q];
    const Mat2 H = displacement_gradient(dN, u);
    const Mat2 F = Mat2::Identity() + H;
    detF_min = std::min(detF_min, F.determinant());
    const Mat2 E = green_lagrange(H);
    const Mat2 S = material.stress(E);
    // B maps nodal displacement variations to (dE11, dE22, 2 dE12).
    for (int k = 0; k < 6; ++k) {
      const double N1 = dN(0, k), N2 = dN(1, k);
      B(0, 2 * k) = F(0, 0) * N1;
      B(0, 2 * k + 1) = F(1, 0) * N1;
      B(1, 2 * k) = F(0, 1) * N2;
      B(1, 2 * k + 1) = F(1, 1) * N2;
      B(2, 2 * k) = F(0, 0) * N2 + F(0, 1) * N1;
      B(2, 2 * k + 1) = F(1, 0) * N2 + F(1, 1) * N1;
    }
    const Eigen::Vector3d S_voigt(S(0, 0), S(1, 1), S(0, 1));
    f.noalias() += w_detJ_[q] * (B.transpose() * S_voigt);
    if (!K) continue;
    const Mat3 D = material.tangent(E);
    K->noalias() += w_detJ_[q] * (B.transpose() * D * B);          // material stiffness
    const Eigen::Matrix<double, 6, 6> G = dN.transpose() * S * dN; // geometric: grad N_I S grad N_J
    for (int a = 0; a < 6; ++a)
      for (int b = 0; b < 6; ++b) {
        (*K)(2 * a, 2 * b) += w_detJ_[q] * G(a, b);
        (*K)(2 * a + 1, 2 * b + 1) += w_detJ_[q] * G(a, b);
      }
  }
  return detF_min;
}

double ElementT6::strain_energy(const Vec12& u, const Material& material) const {
  double W = 0.0;
  for (std::size_t q = 0; q < dNdX_.size(); ++q)
    W += w_detJ_[q] * material.energy(green_lagrange(displacement_gradient(dNdX_[q], u)));
  return W;
}

Mat12 t6_mass(const ElementNodes& X, double rho) {
  const auto C = node_coordinates(X);
  Eigen::Matrix<double, 6, 6> m = Eigen::Matrix<double, 6, 6>::Zero();
  for (const auto& q : rule_degree4) {
    const auto N = t6_shape(q.xi, q.eta);
    const double detJ = jacobian(t6_shape_derivatives(q.xi, q.eta), C).determinant();
    m.noalias() += rho * q.weight * detJ * (N * N.transpose());
  }
  Mat12 M = Mat12::Zero();
  for (int a = 0; a < 6; ++a)
    for (int b = 0; b < 6; ++b) M(2 * a, 2 * b) = M(2 * a + 1, 2 * b + 1) = m(a, b);
  return M;
}

std::array<double, 6> t6_nodal_von_mises(const ElementNodes& X, const Vec12& u,
                                         const Material& material) {
  const auto C = node_coordinates(X);
  std::array<double, 6> vm{};
  for (std::size_t k = 0; k < 6; ++k) {
    const Mat26 dN = t6_shape_derivatives(t6_node_parent[k][0], t6_node_parent[k][1]);
    const Mat2 H = displacement_gradient(jacobian(dN, C).inverse() * dN, u);
    vm[k] = materials::von_mises(material, Mat2::Identity() + H, green_lagrange(H));
  }
  return vm;
}

} // namespace fsi::fem
