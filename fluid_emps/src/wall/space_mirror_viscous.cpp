// The wall's viscous term in 3-D: the mirror Laplacian (eqs. 23-24) and the approach viscosity.
#include "fluid_emps/space_wall_terms.hpp"

#include "geometry_erp/mirror.hpp"

#include <cmath>

namespace fsi::emps {

// At the mirror point x_i' = 2 x_wall - x_i (eq. 23) of face k, over the real neighbours of x_i'
// (j = i included), without the 2d/(lambda0 n0) factor, as WallTerms::mirror_viscous in 2-D:
// the Laplacian with the mirror velocity v_i' (eq. 24 no-slip, or slip) turned back by R_inv or
// R_ref, and with `approach` the closing pairs (i, ghost of j) across the wall, R_ref sum of
// ((v_j - v_i^s) . e) e w.
MirrorViscous3 SpaceWallTerms::mirror_viscous(std::size_t i, std::size_t k, bool approach) const {
  const erp::TriangleHits& f = hits_[k];
  const Vec3 x_wall = f.x_wall[i], n_wall = f.n_wall[i], v_wall = f.v_wall[i];
  const bool no_slip = o_.mirror.condition == WallCondition::no_slip;
  const Vec3 v_i = velocity(i);
  const Vec3 v_m = no_slip ? erp::mirror_velocity_no_slip<3>(v_i, v_wall, n_wall)
                           : erp::mirror_velocity_slip<3>(v_i, v_wall, n_wall);
  const Vec3 v_s = erp::mirror_velocity_slip<3>(v_i, v_wall, n_wall);
  const Vec3 m = 2.0 * x_wall - position(i);
  Vec3 u = Vec3::Zero(), a = Vec3::Zero();
  for_each_within(m, [&](std::uint32_t j) {
    const Vec3 d(p_.position[0][j] - m[0], p_.position[1][j] - m[1], p_.position[2][j] - m[2]);
    const double r2 = d.squaredNorm();
    if (r2 >= re2_ || behind(j, x_wall, n_wall)) return;
    const double w = w_e_.inside(std::sqrt(r2));
    const Vec3 v_j = velocity(j);
    u += (v_j - v_m) * w;
    if (!approach || r2 == 0.0) return;
    const double closing = (v_j - v_s).dot(d);
    if (closing < 0) a += closing * w / r2 * d;
  });
  return {(no_slip ? erp::R_inv<3>() : erp::R_ref<3>(n_wall)) * u, erp::R_ref<3>(n_wall) * a};
}

} // namespace fsi::emps
