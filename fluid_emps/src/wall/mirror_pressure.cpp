// The wall's pressure term: the mirror gradient (eqs. 23, 25-26).
#include "fluid_emps/wall_terms.hpp"

#include "geometry_erp/mirror.hpp"

#include <cmath>

namespace fsi::emps {

// (d/n0) R_ref <grad p>_i' (eqs. 25-26): the gradient sum at the mirror point x_i' = 2 x_wall -
// x_i over the real neighbours of x_i' (j = i included) with p_i' (p_i in eq. 26; see
// WallPressure), reflected back. On the nearest face with convex_corners, the convex corners'
// wedge (virtual particles at p_i') replaces the mirror in proportion to its share.
Vec2 WallTerms::mirror_pressure(std::size_t i, std::size_t k, double p_mirror) const {
  const erp::FaceHits& f = hits_.face[k];
  const Vec2 x_wall = f.x_wall[i], n_wall = f.n_wall[i];
  const double p_i = p_mirror;
  const double mpx = 2.0 * x_wall.x() - p_.x[i], mpy = 2.0 * x_wall.y() - p_.y[i];
  double ux = 0, uy = 0;
  grid_.for_each_near(mpx, mpy, [&](std::uint32_t j) {
    const double dx = p_.x[j] - mpx, dy = p_.y[j] - mpy, r2 = dx * dx + dy * dy;
    if (r2 >= re2_ || r2 == 0.0 || behind(j, x_wall, n_wall)) return;
    const double s = (p_.p[j] + p_i) * w_e_.inside(std::sqrt(r2)) / r2;
    ux += s * dx;
    uy += s * dy;
  });
  Vec2 mirror = erp::R_ref(n_wall) * Vec2(ux, uy);
  if (k == 0 && o_.convex_corners) {
    const erp::ConvexPart part = convex_part(i);
    mirror = (1.0 - part.share) * mirror + part.share * (p_.p[i] + p_mirror) * part.g;
  }
  return dim / n0_ * mirror;
}

} // namespace fsi::emps
