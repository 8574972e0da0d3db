// The wall's viscous term: the mirror Laplacian (eqs. 23-24) and the approach viscosity.
#include "fluid_emps/wall_terms.hpp"

#include "geometry_erp/mirror.hpp"

#include <cmath>

namespace fsi::emps {

// At the mirror point x_i' = 2 x_wall - x_i (eq. 23) of face k, over the real neighbours of x_i'
// (j = i included), without the 2d/(lambda0 n0) factor:
// - laplacian: <lap v>_i' with the mirror velocity v_i' (eq. 24 no-slip, or slip), turned back by
//   R_inv (no-slip) or R_ref (slip);
// - approach (with `approach`): the closing-pair sum of the pairs (i, ghost of j) that close in
//   across the wall. The ghost of j sits at the reflection of x_j and moves with v_wall +
//   R_ref (v_j - v_wall); R_ref maps x_j - x_i' to the pair's separation and v_j - v_i^s to its
//   relative velocity (v_i^s: i's slip mirror velocity), so the sum is R_ref sum over closing
//   pairs of ((v_j - v_i^s) . e) e w, e and r those of x_j - x_i' (as the fluid's closing pairs).
MirrorViscous WallTerms::mirror_viscous(std::size_t i, std::size_t k, bool approach) const {
  const erp::FaceHits& f = hits_.face[k];
  const Vec2 x_wall = f.x_wall[i], n_wall = f.n_wall[i], v_wall = f.v_wall[i];
  const bool no_slip = o_.mirror.condition == WallCondition::no_slip;
  const Vec2 v_i(p_.vx[i], p_.vy[i]);
  const Vec2 v_m = no_slip ? erp::mirror_velocity_no_slip(v_i, v_wall, n_wall)
                           : erp::mirror_velocity_slip(v_i, v_wall, n_wall);
  const Vec2 v_s = erp::mirror_velocity_slip(v_i, v_wall, n_wall);
  const double mpx = 2.0 * x_wall.x() - p_.x[i], mpy = 2.0 * x_wall.y() - p_.y[i];
  double ux = 0, uy = 0, ax = 0, ay = 0;
  grid_.for_each_near(mpx, mpy, [&](std::uint32_t j) {
    const double dx = p_.x[j] - mpx, dy = p_.y[j] - mpy, r2 = dx * dx + dy * dy;
    if (r2 >= re2_ || behind(j, x_wall, n_wall)) return;
    const double w = w_e_.inside(std::sqrt(r2));
    ux += (p_.vx[j] - v_m.x()) * w;
    uy += (p_.vy[j] - v_m.y()) * w;
    if (!approach || r2 == 0.0) return;
    const double closing = (p_.vx[j] - v_s.x()) * dx + (p_.vy[j] - v_s.y()) * dy;
    if (closing >= 0) return;
    ax += closing * w / r2 * dx;
    ay += closing * w / r2 * dy;
  });
  return {(no_slip ? erp::R_inv() : erp::R_ref(n_wall)) * Vec2(ux, uy),
          erp::R_ref(n_wall) * Vec2(ax, ay)};
}

} // namespace fsi::emps
