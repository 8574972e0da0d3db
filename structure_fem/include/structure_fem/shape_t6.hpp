#pragma once
// Shape functions of the 6-node isoparametric triangle (eqs. 37-39) and the quadrature rules on
// the reference triangle {xi >= 0, eta >= 0, xi + eta <= 1} (area 1/2).
// Node order: corners 0, 1, 2, then mid-nodes 3 (0-1), 4 (1-2), 5 (2-0).
#include <array>

#include <Eigen/Core>

namespace fsi::fem {

struct QuadraturePoint {
  double xi, eta, weight; // weights sum to the reference area 1/2
};

/// 3-point rule (points at 1/6, 2/3), exact for degree 2: the stiffness integrand B^T D B of a
/// straight-sided T6 (B linear) and the strain energy of a linear field are integrated exactly.
inline constexpr std::array<QuadraturePoint, 3> rule_degree2{{{1.0 / 6.0, 1.0 / 6.0, 1.0 / 6.0},
                                                              {2.0 / 3.0, 1.0 / 6.0, 1.0 / 6.0},
                                                              {1.0 / 6.0, 2.0 / 3.0, 1.0 / 6.0}}};

/// 6-point Strang–Fix/Dunavant rule, exact for degree 4: the consistent mass N_I N_J (degree 4).
inline constexpr double dunavant_a = 0.445948490915965, dunavant_wa = 0.5 * 0.223381589678011;
inline constexpr double dunavant_b = 0.091576213509771, dunavant_wb = 0.5 * 0.109951743655322;
inline constexpr std::array<QuadraturePoint, 6> rule_degree4{
    {{dunavant_a, dunavant_a, dunavant_wa},
     {1.0 - 2.0 * dunavant_a, dunavant_a, dunavant_wa},
     {dunavant_a, 1.0 - 2.0 * dunavant_a, dunavant_wa},
     {dunavant_b, dunavant_b, dunavant_wb},
     {1.0 - 2.0 * dunavant_b, dunavant_b, dunavant_wb},
     {dunavant_b, 1.0 - 2.0 * dunavant_b, dunavant_wb}}};

/// Parent coordinates of the six nodes.
inline constexpr std::array<std::array<double, 2>, 6> t6_node_parent{
    {{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}, {0.5, 0.0}, {0.5, 0.5}, {0.0, 0.5}}};

/// N_K(xi, eta) with area coordinates L1 = 1 - xi - eta, L2 = xi, L3 = eta.
inline Eigen::Matrix<double, 6, 1> t6_shape(double xi, double eta) {
  const double L1 = 1.0 - xi - eta, L2 = xi, L3 = eta;
  Eigen::Matrix<double, 6, 1> N;
  N << L1 * (2 * L1 - 1), L2 * (2 * L2 - 1), L3 * (2 * L3 - 1), 4 * L1 * L2, 4 * L2 * L3,
      4 * L3 * L1;
  return N;
}

/// Row 0: dN_K/dxi, row 1: dN_K/deta.
inline Eigen::Matrix<double, 2, 6> t6_shape_derivatives(double xi, double eta) {
  const double L1 = 1.0 - xi - eta, L2 = xi, L3 = eta;
  Eigen::Matrix<double, 2, 6> dN;
  dN << -(4 * L1 - 1), 4 * L2 - 1, 0.0, 4 * (L1 - L2), 4 * L3, -4 * L3, //
      -(4 * L1 - 1), 0.0, 4 * L3 - 1, -4 * L2, 4 * L2, 4 * (L1 - L3);
  return dN;
}

/// Shape functions of a 3-node edge (corner a, mid, corner b) at s in [-1, 1].
inline Eigen::Vector3d edge3_shape(double s) {
  return {0.5 * s * (s - 1.0), 1.0 - s * s, 0.5 * s * (s + 1.0)};
}
inline Eigen::Vector3d edge3_shape_derivative(double s) {
  return {s - 0.5, -2.0 * s, s + 0.5};
}

} // namespace fsi::fem
