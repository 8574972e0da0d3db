// The wall's pressure term in 3-D behind two or three walls: the images of the lattice in the
// quadrant of a concave edge and the octant of a corner (eqs. 23, 25-26 across several planes).
#include "fluid_emps/space_wall_terms.hpp"

#include "geometry_erp/mirror.hpp"

#include <cmath>

namespace fsi::emps {

// One face's mirror (eqs. 25-26) images the real fluid behind that plane only; the lattice behind
// two planes (and three) belongs to no single mirror. Its image is the fluid reflected across each
// of them: x_i'' = ref_l(ref_k(x_i)) (x_i reflected across each plane in turn), the real fluid's
// image F(x_j) with F = ref_k o ref_l its inverse, |F(x_j) - x_i| = |x_j - x_i''|. The sum of
// eq. 25 over the real neighbours of x_i'' with p_i' = p_i (eq. 26) is turned back by F's linear
// part R_ref(n_k) R_ref(n_l) (three planes alike). Each pair of faces is counted once and the
// three once, as the lattice in SpaceWallTerms::pnd (exact at right angles; another turn scales
// each image by turn_share, the corner's by the product of its three pairs').
Vec3 SpaceWallTerms::corner_mirror_pressure(std::size_t i, unsigned replaced) const {
  std::array<std::size_t, max_faces3> on{};
  const std::size_t faces = acting_faces(i, on, replaced);
  if (faces < 2) return Vec3::Zero();
  const double p_i = p_.p[i];
  // The image across faces on[a] for a in `set` (bit a): its gradient sum, turned back.
  const auto image = [&](unsigned set) {
    Vec3 m = position(i);
    Mat3 turn = Mat3::Identity(); // F's linear part; m = x_i''
    for (std::size_t a = 0; a < faces; ++a) {
      if (!(set >> a & 1u)) continue;
      const Vec3 &x_wall = hits_[on[a]].x_wall[i], &n_wall = hits_[on[a]].n_wall[i];
      m -= 2.0 * (m - x_wall).dot(n_wall) * n_wall;
      turn = turn * erp::R_ref<3>(n_wall);
    }
    Vec3 u = Vec3::Zero();
    for_each_within(m, [&](std::uint32_t j) {
      const Vec3 d(p_.position[0][j] - m[0], p_.position[1][j] - m[1], p_.position[2][j] - m[2]);
      const double r2 = d.squaredNorm();
      if (r2 >= re2_ || r2 == 0.0) return;
      for (std::size_t a = 0; a < faces; ++a)
        if ((set >> a & 1u) && behind(j, hits_[on[a]].x_wall[i], hits_[on[a]].n_wall[i])) return;
      u += (p_.p[j] + p_i) * w_e_.inside(std::sqrt(r2)) / r2 * d;
    });
    return Vec3(turn * u);
  };
  const auto n = [&](std::size_t a) -> const Vec3& { return hits_[on[a]].n_wall[i]; };
  Vec3 u = Vec3::Zero();
  for (std::size_t a = 1; a < faces; ++a)
    for (std::size_t b = 0; b < a; ++b) u += turn_share(n(b), n(a)) * image(1u << a | 1u << b);
  if (faces == 3)
    u += turn_share(n(0), n(1)) * turn_share(n(0), n(2)) * turn_share(n(1), n(2)) * image(7u);
  return 3.0 / n0_ * u;
}

} // namespace fsi::emps
