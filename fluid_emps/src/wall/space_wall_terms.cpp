#include "fluid_emps/space_wall_terms.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace fsi::emps {

SpaceWallTerms::SpaceWallTerms(const FluidOptions3& options, double n0, const Particles3& particles,
                               const particles::BasicCellGrid<3>& grid, const SpaceHits& hits,
                               const erp::ConvexFaces& convex)
    : o_(options.wall), l0_(options.l0), r_e_(options.r_e()), re2_(r_e_ * r_e_),
      rho_(options.density), c_(options.sound_speed), n0_(n0), w_e_(r_e_),
      z_(options.l0, r_e_, particles::MpsWeight(r_e_)), p_(particles), grid_(grid), hits_(hits),
      convex_(convex) {}

// With MirrorOptions::same_side: j lies behind the face's plane (x_wall, n_wall), on the far side
// of a thin wall, so the mirror sums leave it out.
bool SpaceWallTerms::behind(std::uint32_t j, const Vec3& x_wall, const Vec3& n_wall) const {
  if (!o_.mirror.same_side) return false;
  double s = 0.0;
  for (int a = 0; a < 3; ++a) s += (p_.position[a][j] - x_wall[a]) * n_wall[a];
  return s < 0.0;
}

double SpaceWallTerms::turn_share(const Vec3& n1, const Vec3& n2) {
  return std::acos(std::clamp(n1.dot(n2), -1.0, 1.0)) / (0.5 * std::numbers::pi);
}

std::size_t SpaceWallTerms::acting_faces(std::size_t i, std::array<std::size_t, max_faces3>& on,
                                         unsigned replaced) const {
  std::size_t faces = 0;
  for (std::size_t k = 0; k < max_faces3; ++k)
    if (hits_[k].triangle[i] >= 0 && !(replaced >> k & 1u)) on[faces++] = k;
  return faces;
}

} // namespace fsi::emps
