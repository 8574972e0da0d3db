// Contact of a particle with a triangle face (3-D): the repulsive term (eq. 27) and
// WallContact::damped, as WallTerms::contact in 2-D.
#include "contact_law.hpp"
#include "fluid_emps/space_wall_terms.hpp"

namespace fsi::emps {

Vec3 SpaceWallTerms::contact(std::size_t i, std::size_t k, double dt) const {
  const erp::TriangleHits& f = hits_[k];
  return wall_contact(o_.contact, f.r[i], f.n_wall[i], Vec3(velocity(i) - f.v_wall[i]), l0_, c_,
                      rho_, dt);
}

} // namespace fsi::emps
