// Contact of a particle with a wall face: the repulsive term (eq. 27) and WallContact::damped.
#include "fluid_emps/wall_terms.hpp"

#include <algorithm>
#include <cmath>

namespace fsi::emps {

Vec2 WallTerms::contact(std::size_t i, std::size_t k, double dt) const {
  const erp::FaceHits& f = hits_.face[k];
  Vec2 out = repulsion(f.r[i], f.n_wall[i]);
  if (o_.contact.model == WallContact::damped)
    out += normal_damping(i, f.r[i], f.n_wall[i], f.v_wall[i], dt);
  return out;
}

// f_rep (eq. 27), in the units of grad p; r is floored at l0/2000 (a particle on the wall).
Vec2 WallTerms::repulsion(double r, const Vec2& n_wall) const {
  const double half_l0 = 0.5 * l0_;
  if (r >= half_l0) return Vec2::Zero();
  return -o_.contact.alpha_rep * (half_l0 / std::max(r, 1e-3 * half_l0) - 1.0) * n_wall;
}

// WallContact::damped: the wall-normal approach velocity u_n = (v*_i - v_wall).n < 0 within l0
// of a wall loses the fraction 1 - exp(-gamma dt) in this step, gamma = wall_damping c/l0 (1 -
// r/l0): rho/dt (1 - exp(-gamma dt)) u_n n in the units of grad p (added to it, as f_rep).
// Separation is not resisted; the restitution of a particle stopped within l0 is that of f_rep.
Vec2 WallTerms::normal_damping(std::size_t i, double r, const Vec2& n_wall, const Vec2& v_wall,
                               double dt) const {
  if (r >= l0_) return Vec2::Zero();
  const double u_n = (Vec2(p_.vx[i], p_.vy[i]) - v_wall).dot(n_wall);
  if (u_n >= 0.0) return Vec2::Zero();
  const double gamma = o_.contact.damping * c_ / l0_ * (1.0 - r / l0_);
  return rho_ / dt * (1.0 - std::exp(-gamma * dt)) * u_n * n_wall;
}

} // namespace fsi::emps
