// Contact of a particle with a wall face: the repulsive term (eq. 27) and WallContact::damped.
#include "contact_law.hpp"
#include "fluid_emps/wall_terms.hpp"

namespace fsi::emps {

Vec2 WallTerms::contact(std::size_t i, std::size_t k, double dt) const {
  const erp::FaceHits& f = hits_.face[k];
  return wall_contact(o_.contact, f.r[i], f.n_wall[i], Vec2(Vec2(p_.vx[i], p_.vy[i]) - f.v_wall[i]),
                      l0_, c_, rho_, dt);
}

} // namespace fsi::emps
