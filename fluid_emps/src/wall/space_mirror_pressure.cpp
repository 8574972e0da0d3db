// The wall's pressure term in 3-D: the mirror gradient (eqs. 23, 25-26) across a triangle's plane.
#include "fluid_emps/space_wall_terms.hpp"

#include "geometry_erp/mirror.hpp"

#include <cmath>

namespace fsi::emps {

// (d/n0) R_ref <grad p>_i' (eqs. 25-26): the gradient sum at the mirror point x_i' = 2 x_wall -
// x_i over the real neighbours of x_i' (j = i included) with p_i' = p_i (eq. 26), reflected back.
Vec3 SpaceWallTerms::mirror_pressure(std::size_t i, std::size_t k) const {
  const erp::TriangleHits& f = hits_[k];
  const Vec3 x_wall = f.x_wall[i], n_wall = f.n_wall[i];
  const double p_i = p_.p[i];
  const Vec3 m = 2.0 * x_wall - position(i);
  Vec3 u = Vec3::Zero();
  for_each_within(m, [&](std::uint32_t j) {
    const Vec3 d(p_.position[0][j] - m[0], p_.position[1][j] - m[1], p_.position[2][j] - m[2]);
    const double r2 = d.squaredNorm();
    if (r2 >= re2_ || r2 == 0.0 || behind(j, x_wall, n_wall)) return;
    u += (p_.p[j] + p_i) * w_e_.inside(std::sqrt(r2)) / r2 * d;
  });
  return 3.0 / n0_ * Vec3(erp::R_ref<3>(n_wall) * u);
}

} // namespace fsi::emps
