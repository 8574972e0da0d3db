#include "fluid_emps/wall_terms.hpp"

namespace fsi::emps {

WallTerms::WallTerms(const FluidOptions& options, double n0, const erp::WallSet& walls,
                     const Particles& particles, const particles::CellGrid& grid,
                     const erp::WallHits& hits)
    : o_(options.wall), l0_(options.l0), r_e_(options.r_e()), re2_(r_e_ * r_e_),
      rho_(options.density), c_(options.sound_speed), n0_(n0), w_e_(r_e_),
      z_(options.l0, r_e_, particles::MpsWeight(r_e_)), walls_(walls), p_(particles), grid_(grid),
      hits_(hits) {}

// With MirrorOptions::same_side: j lies behind the wall of the hit (x_wall, n_wall), on the far
// side of a thin wall, so the mirror sums leave it out (its image would land on the particle's
// side).
bool WallTerms::behind(std::uint32_t j, const Vec2& x_wall, const Vec2& n_wall) const {
  return o_.mirror.same_side &&
         (p_.x[j] - x_wall.x()) * n_wall.x() + (p_.y[j] - x_wall.y()) * n_wall.y() < 0.0;
}

// The convex corners of particle i's nearest segment (geometry_erp convex_part).
erp::ConvexPart WallTerms::convex_part(std::size_t i) const {
  const erp::FaceHits& f = hits_.face[0];
  return erp::convex_part(walls_, f.segment[i], f.t[i], Vec2(p_.x[i], p_.y[i]), f.r[i], f.n_wall[i],
                          z_, l0_, r_e_, w_e_);
}

} // namespace fsi::emps
