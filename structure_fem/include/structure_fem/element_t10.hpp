#pragma once
// Total-Lagrangian 10-node tetrahedron (issue 44): internal force, consistent tangent (material +
// geometric), consistent mass, volume and nodal von Mises stress. Element vectors are ordered
// (u_0x, u_0y, u_0z, u_1x, ..., u_9z); node order of shape_t10.hpp (Gmsh type 11).
#include <array>

#include "structure_fem/material.hpp"
#include "structure_fem/types.hpp"

namespace fsi::fem {

using Vec30 = Eigen::Matrix<double, 30, 1>;
using Mat30 = Eigen::Matrix<double, 30, 30>;
using TetNodes = std::array<Vec3, 10>;

/// Smallest det J of the reference map over the ten nodes and the points of both rules.
double t10_min_jacobian(const TetNodes& X);
/// Reference volume, integral of det J (tet_rule_degree5: exact for straight and curved edges,
/// det J being of degree 3).
double t10_volume(const TetNodes& X);

class ElementT10 {
public:
  /// Precomputes dN/dX and w det J at the stiffness quadrature points (tet_rule_degree2).
  explicit ElementT10(const TetNodes& X);

  /// f_int = sum_q w det J0 B^T S and, if K is given, K = sum_q w det J0 (B^T C B + G).
  /// Returns the smallest det F over the quadrature points; if it is <= 0, f and K are not valid.
  double internal_force(const Vec30& u, const Material3& material, Vec30& f, Mat30* K) const;
  /// integral of W(E) over the element (same quadrature as the internal force).
  double strain_energy(const Vec30& u, const Material3& material) const;

private:
  std::array<Eigen::Matrix<double, 3, 10>, 4> dNdX_; ///< dN_K/dX_j at each stiffness point
  std::array<double, 4> w_detJ_;
};

/// Consistent mass M = integral rho N^T N (tet_rule_degree5, exact for straight edges).
Mat30 t10_mass(const TetNodes& X, double rho);
/// Von Mises equivalent of the Cauchy stress sigma = F S F^T / det F, evaluated at the ten nodes.
std::array<double, 10> t10_nodal_von_mises(const TetNodes& X, const Vec30& u,
                                           const Material3& material);

} // namespace fsi::fem
