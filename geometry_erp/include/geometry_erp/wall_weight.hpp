#pragma once
// Wall weight z(r) (eq. 20) and the lattice constants n0 (eq. 9) and lambda0 (eq. 12), all on the
// same lattice of spacing l0: square for D = 2, cubic for D = 3 (template <int D = 2>).
//
// Lattice of z: a flat wall at y = 0 (z = 0 in 3-D), fluid rows (layers) at l0/2 + k l0 (k >= 0)
// from it, virtual rows behind the wall at -l0/2 - m l0 (m >= 0), the continuation of the fluid
// lattice; columns at x = i l0 (and y = j l0 in 3-D) aligned with the particle at distance r.
// z(r) = sum of w over the virtual particles, so a particle on a fluid row with a full fluid
// lattice around it has n_i + z(r) = n0 exactly.
#include "fsi/core/types.hpp"
#include "geometry_erp/cubic_spline.hpp"
#include "particles/kernels.hpp"

#include <functional>

namespace fsi::erp {

/// A weight function of distance, zero at and beyond r_e (particles::MpsWeight or a replacement).
using WeightFunction = std::function<double(double)>;

/// z(r) by direct summation over the virtual half-lattice.
template <int D = 2>
double wall_weight_sum(double r, double l0, double r_e, const WeightFunction& w);

/// The virtual lattice counted by both faces of a right-angle corner: a particle at distances a
/// and b from the two walls, virtual points at (a + l0/2 + m l0, b + l0/2 + k l0) behind both
/// (m, k >= 0). z(a) + z(b) - q(a, b) is the wall part of pnd in the corner, exact on the lattice.
double corner_weight_sum(double a, double b, double l0, double r_e, const WeightFunction& w);

/// The 3-D counterparts on the cubic lattice: the virtual lattice behind both walls of a
/// right-angle concave edge (walls at distances a and b, the lattice's columns along the edge
/// aligned with the particle), q3(a, b) = sum_{m,k >= 0} sum_j w(|(a + l0/2 + m l0, b + l0/2 + k
/// l0, j l0)|), and behind all three walls of a right-angle corner, o(a, b, c) = sum_{m,k,l >= 0}
/// w(|(a + l0/2 + m l0, b + l0/2 + k l0, c + l0/2 + l l0)|). By inclusion-exclusion z(a) + z(b) +
/// z(c) - q3(a, b)
/// - q3(a, c) - q3(b, c) + o(a, b, c) is the wall part of pnd in the corner, exact on the lattice.
double edge_weight_sum3(double a, double b, double l0, double r_e, const particles::MpsWeight& w);
double corner_weight_sum3(double a, double b, double c, double l0, double r_e,
                          const particles::MpsWeight& w);

/// Eq. 10's geometric sum over the same virtual half-lattice as z(r): sum of (dy / rho^2) w(rho),
/// dy the depth of a virtual point below the particle and rho its distance. With every virtual
/// particle at pressure p_i, the wall part of <grad p>_i is -(d / n0) 2 p_i times this along n.
template <int D = 2>
double wall_gradient_sum(double r, double l0, double r_e, const WeightFunction& w);

/// The same for corner_weight_sum's quadrant: the components (sum da / rho^2 w, sum db / rho^2 w)
/// along the directions in which a and b grow, virtual points at da = a + l0/2 + m l0,
/// db = b + l0/2 + k l0.
Vec2 corner_gradient_sum(double a, double b, double l0, double r_e, const WeightFunction& w);

/// n0 = sum_{j != i} w(|x_j - x_i|) over the full D-dimensional cubic lattice of spacing l0
/// (eq. 9): the square lattice for D = 2 (the 2-D solvers), the cubic one for D = 3.
template <int D = 2> double lattice_n0(double l0, double r_e, const WeightFunction& w);

/// lambda0 = sum_{j != i} |x_j - x_i|^2 w / sum_{j != i} w over the same lattice (eq. 12).
template <int D = 2> double lattice_lambda0(double l0, double r_e, const WeightFunction& w);

/// z(r) tabulated once and interpolated by a natural cubic spline. z = 0 from r = r_e - l0/2 on
/// (the nearest virtual row is l0/2 behind the wall), so the table spans [0, r_e - l0/2]. The
/// knots are multiples of l0 / (2 M), M chosen for at least `min_intervals` intervals over r_e, so
/// every fluid row r = l0/2 + k l0 is a knot. WallWeightTable on the square lattice,
/// WallWeightTable3 on the cubic one.
template <int D> class BasicWallWeightTable {
public:
  BasicWallWeightTable(double l0, double r_e, const WeightFunction& w, int min_intervals = 1000);
  /// z(r); z(r) = z(0) for r < 0 and 0 for r >= r_e - l0/2.
  double operator()(double r) const { return r >= r_zero_ ? 0.0 : z_(r).y; }
  double dz_dr(double r) const { return r >= r_zero_ ? 0.0 : z_(r).dy; }
  double l0() const { return l0_; }
  double r_e() const { return r_e_; }
  /// Knot spacing of the table.
  double spacing() const { return dr_; }

private:
  double l0_, r_e_, r_zero_, dr_;
  CubicSpline z_;
};

using WallWeightTable = BasicWallWeightTable<2>;
using WallWeightTable3 = BasicWallWeightTable<3>;

extern template double wall_weight_sum<2>(double, double, double, const WeightFunction&);
extern template double wall_weight_sum<3>(double, double, double, const WeightFunction&);
extern template double wall_gradient_sum<2>(double, double, double, const WeightFunction&);
extern template double wall_gradient_sum<3>(double, double, double, const WeightFunction&);
extern template class BasicWallWeightTable<2>;
extern template class BasicWallWeightTable<3>;

} // namespace fsi::erp
