#pragma once
// Shape functions of the 10-node quadratic tetrahedron (T10) and the quadrature rules on the
// reference tetrahedron {xi, eta, zeta >= 0, xi + eta + zeta <= 1} (volume 1/6).
// Node order of Gmsh (type 11): vertices 0 (0,0,0), 1 (1,0,0), 2 (0,1,0),
// 3 (0,0,1), then edge nodes 4 (0-1), 5 (1-2), 6 (2-0), 7 (3-0), 8 (3-2), 9 (3-1) (checked
// against a `gmsh -3 -order 2` tetrahedron: each edge node at its edge's midpoint). CalculiX and
// Abaqus C3D10 swap the last two: our nodes 8 (3-2) and 9 (3-1) are their 10th and 9th nodes.
#include <array>

#include <Eigen/Core>

namespace fsi::fem {

struct TetQuadraturePoint {
  double xi, eta, zeta, weight; // weights sum to the reference volume 1/6
};

/// The 4 points with volume coordinates (a, a, a, 1 - 3a) in any order, each of weight w.
constexpr std::array<TetQuadraturePoint, 4> tet_orbit4(double a, double w) {
  const double b = 1.0 - 3.0 * a;
  return {{{a, a, a, w}, {b, a, a, w}, {a, b, a, w}, {a, a, b, w}}};
}

/// 4-point rule, exact for degree 2 (a = (5 - sqrt 5)/20, weights 1/24): the stiffness integrand
/// B^T D B of a straight-sided T10 (B linear).
inline constexpr std::array<TetQuadraturePoint, 4> tet_rule_degree2 =
    tet_orbit4(0.13819660112501051518, 1.0 / 24.0);

/// 14-point rule with positive weights, exact for degree 5 (Walkington, "Quadrature on simplices
/// of arbitrary dimension", 2000; Gellert & Harbord, Commun. Appl. Numer. Methods 7, 1991):
/// 4 points (a, a, a, 1 - 3a) for each of a1, a2, and the 6 points (c, c, 1/2 - c, 1/2 - c). It
/// integrates the consistent mass N_I N_J (degree 4) of a straight-sided T10 and the volume of a
/// curved one (det J of degree 3) exactly.
inline constexpr std::array<TetQuadraturePoint, 14> tet_rule_degree5 = [] {
  constexpr double c = 0.045503704125649649492, d = 0.5 - c, w3 = 0.0070910034628469110730;
  const auto o1 = tet_orbit4(0.31088591926330060980, 0.018781320953002641800);
  const auto o2 = tet_orbit4(0.092735250310891226402, 0.012248840519393658257);
  std::array<TetQuadraturePoint, 14> rule{{o1[0],
                                           o1[1],
                                           o1[2],
                                           o1[3],
                                           o2[0],
                                           o2[1],
                                           o2[2],
                                           o2[3],
                                           {c, c, d, w3},
                                           {c, d, c, w3},
                                           {d, c, c, w3},
                                           {c, d, d, w3},
                                           {d, c, d, w3},
                                           {d, d, c, w3}}};
  return rule;
}();

/// The two vertices of edge node 4 + e.
inline constexpr std::array<std::array<int, 2>, 6> t10_edges{
    {{0, 1}, {1, 2}, {2, 0}, {3, 0}, {3, 2}, {3, 1}}};

/// The four faces as 6-node triangles (corners, then mid-nodes 0-1, 1-2, 2-0), each
/// counter-clockwise seen from outside a positively oriented element: the faces opposite
/// vertices 3, 2, 0 and 1.
inline constexpr std::array<std::array<int, 6>, 4> t10_faces{
    {{0, 2, 1, 6, 5, 4}, {0, 1, 3, 4, 9, 7}, {1, 2, 3, 5, 8, 9}, {0, 3, 2, 7, 8, 6}}};

/// Parent coordinates of the ten nodes.
inline constexpr std::array<std::array<double, 3>, 10> t10_node_parent{{{0.0, 0.0, 0.0},
                                                                        {1.0, 0.0, 0.0},
                                                                        {0.0, 1.0, 0.0},
                                                                        {0.0, 0.0, 1.0},
                                                                        {0.5, 0.0, 0.0},
                                                                        {0.5, 0.5, 0.0},
                                                                        {0.0, 0.5, 0.0},
                                                                        {0.0, 0.0, 0.5},
                                                                        {0.0, 0.5, 0.5},
                                                                        {0.5, 0.0, 0.5}}};

/// Volume coordinates L0 = 1 - xi - eta - zeta, L1 = xi, L2 = eta, L3 = zeta.
inline Eigen::Vector4d tet_volume_coordinates(double xi, double eta, double zeta) {
  return {1.0 - xi - eta - zeta, xi, eta, zeta};
}

/// N_K: vertices L_K (2 L_K - 1), edge nodes 4 L_a L_b.
inline Eigen::Matrix<double, 10, 1> t10_shape(double xi, double eta, double zeta) {
  const Eigen::Vector4d L = tet_volume_coordinates(xi, eta, zeta);
  Eigen::Matrix<double, 10, 1> N;
  for (int k = 0; k < 4; ++k) N(k) = L(k) * (2.0 * L(k) - 1.0);
  for (int e = 0; e < 6; ++e) {
    const auto [a, b] = t10_edges[static_cast<std::size_t>(e)];
    N(4 + e) = 4.0 * L(a) * L(b);
  }
  return N;
}

/// Row i: dN_K / d(xi, eta, zeta)_i.
inline Eigen::Matrix<double, 3, 10> t10_shape_derivatives(double xi, double eta, double zeta) {
  const Eigen::Vector4d L = tet_volume_coordinates(xi, eta, zeta);
  Eigen::Matrix<double, 3, 4> dL; // dL_k / dxi_i
  dL << -1.0, 1.0, 0.0, 0.0,      //
      -1.0, 0.0, 1.0, 0.0,        //
      -1.0, 0.0, 0.0, 1.0;
  Eigen::Matrix<double, 3, 10> dN;
  for (int k = 0; k < 4; ++k) dN.col(k) = (4.0 * L(k) - 1.0) * dL.col(k);
  for (int e = 0; e < 6; ++e) {
    const auto [a, b] = t10_edges[static_cast<std::size_t>(e)];
    dN.col(4 + e) = 4.0 * (L(a) * dL.col(b) + L(b) * dL.col(a));
  }
  return dN;
}

} // namespace fsi::fem
