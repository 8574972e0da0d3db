#pragma once
// Total-Lagrangian 6-node triangle: internal force, consistent tangent (material + geometric),
// consistent mass, strain energy and nodal Cauchy stress. Per unit thickness. Element vectors
// are ordered (u_0x, u_0y, u_1x, ..., u_5y).
#include <array>

#include "structure_fem/material.hpp"
#include "structure_fem/types.hpp"

namespace fsi::fem {

using ElementNodes = std::array<Vec2, 6>;

/// Smallest det J of the reference map over the corners, mid-nodes and all quadrature points.
double t6_min_jacobian(const ElementNodes& X);
/// Reference area, integral of det J (exact for straight and curved sides with the degree-2 rule).
double t6_area(const ElementNodes& X);

class ElementT6 {
public:
  /// Precomputes dN/dX and w det J at the stiffness quadrature points (rule_degree2).
  explicit ElementT6(const ElementNodes& X);

  /// f_int = sum_q w det J0 B^T S and, if K is given, K = sum_q w det J0 (B^T D B + G).
  /// Returns the smallest det F over the quadrature points; if it is <= 0, f and K are not valid.
  double internal_force(const Vec12& u, const Material& material, Vec12& f, Mat12* K) const;
  /// integral of W(E) over the element (same quadrature as the internal force).
  double strain_energy(const Vec12& u, const Material& material) const;

private:
  std::array<Eigen::Matrix<double, 2, 6>, 3> dNdX_; ///< dN_K/dX_j at each stiffness point
  std::array<double, 3> w_detJ_;
};

/// Consistent mass  M = integral rho N^T N (rule_degree4, exact for straight sides).
Mat12 t6_mass(const ElementNodes& X, double rho);
/// Von Mises equivalent of the Cauchy stress sigma = F S F^T / det F (with the out-of-plane
/// component of the plane model), evaluated at the six nodes.
std::array<double, 6> t6_nodal_von_mises(const ElementNodes& X, const Vec12& u,
                                         const Material& material);

} // namespace fsi::fem
