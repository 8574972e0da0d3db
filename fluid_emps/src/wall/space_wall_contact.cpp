// Contact of a particle with a triangle face (3-D): the repulsive term (eq. 27) and
// WallContact::damped, as WallTerms::contact in 2-D.
#include "fluid_emps/space_wall_terms.hpp"

#include <algorithm>
#include <cmath>

namespace fsi::emps {

// f_rep (eq. 27) in the units of grad p, r floored at l0/2000; with WallContact::damped, within l0
// of the wall, rho/dt (1 - exp(-gamma dt)) u_n n for an approach u_n = (v*_i - v_wall).n < 0,
// gamma = wall_damping c/l0 (1 - r/l0).
Vec3 SpaceWallTerms::contact(std::size_t i, std::size_t k, double dt) const {
  const erp::TriangleHits& f = hits_[k];
  const double r = f.r[i], half_l0 = 0.5 * l0_;
  const Vec3& n = f.n_wall[i];
  Vec3 out = Vec3::Zero();
  if (r < half_l0) out = -o_.contact.alpha_rep * (half_l0 / std::max(r, 1e-3 * half_l0) - 1.0) * n;
  if (o_.contact.model != WallContact::damped || r >= l0_) return out;
  const double u_n = (velocity(i) - f.v_wall[i]).dot(n);
  if (u_n >= 0.0) return out;
  const double gamma = o_.contact.damping * c_ / l0_ * (1.0 - r / l0_);
  return out + rho_ / dt * (1.0 - std::exp(-gamma * dt)) * u_n * n;
}

} // namespace fsi::emps
