// The contact of a particle with one wall face, in 2-D and 3-D alike: the repulsive term (eq. 27),
// WallContact::damped's normal damping and the wall-gap step limit, in the units of grad p.
#pragma once

#include "fluid_emps/options.hpp"

#include <algorithm>
#include <cmath>

namespace fsi::emps {

/// f_rep (eq. 27) for a particle at gap r from a face of outward normal n_wall, r floored at
/// l0/2000 (a particle on the wall); with WallContact::damped, within l0 of the wall, the approach
/// u_n = (v*_i - v_wall).n < 0 (u = v*_i - v_wall) loses the fraction 1 - exp(-gamma dt) in this
/// step, gamma = wall_damping c/l0 (1 - r/l0): rho/dt (1 - exp(-gamma dt)) u_n n, added as f_rep
/// is. Separation is not resisted; the restitution of a particle stopped within l0 is f_rep's.
template <class Vec>
Vec wall_contact(const WallContactOptions& o, double r, const Vec& n_wall, const Vec& u, double l0,
                 double c, double rho, double dt) {
  const double half_l0 = 0.5 * l0;
  Vec out = Vec::Zero();
  if (r < half_l0) out = -o.alpha_rep * (half_l0 / std::max(r, 1e-3 * half_l0) - 1.0) * n_wall;
  if (o.model != WallContact::damped || r >= l0) return out;
  const double u_n = u.dot(n_wall);
  if (u_n >= 0.0) return out;
  const double gamma = o.damping * c / l0 * (1.0 - r / l0);
  return out + rho / dt * (1.0 - std::exp(-gamma * dt)) * u_n * n_wall;
}

/// The wall-gap limit on one face (WallOptions::gap_courant): dt <= C_gap r / approach, the gap r
/// at x^{n+1} to first order floored at l0/2000 as in wall_contact, approach = -(v - v_wall).n > 0.
inline double gap_limit(double gap, double approach, double l0, double gap_courant) {
  return gap_courant * std::max(gap, 0.5e-3 * l0) / approach;
}

} // namespace fsi::emps
