// Eq. 52's mapping in 3-D: a particle's wall-term shares as forces on triangles.
#include "fluid_emps/space_wall_terms.hpp"

namespace fsi::emps {

// f_wall = -V (R_ref <grad p>_i' + f_rep) (eq. 52's pressure and contact part): a face's
// share at its x_wall (hits[k]), a convex piece's at the particle's nearest point on its seed
// triangle, so that a solid seeding a piece of its own (the box beyond the foot of its vertical
// edge, the floor nearest) takes its piece's force, not the nearest face.
void SpaceWallTerms::record_forces(std::size_t i, const WallShares3& shares, double V,
                                   WallForces3& forces) const {
  for (std::size_t k = 0; k < max_faces3; ++k) {
    TriangleForces& f = forces[k];
    const int t = hits_[k].triangle[i];
    f.triangle[i] = t;
    f.bary[i] = t >= 0 ? hits_[k].bary[i] : Vec3::Zero();
    f.f[i] = t >= 0 ? Vec3(-V * shares[k]) : Vec3::Zero();
  }
  if (!o_.convex_corners) return; // no pieces, their slots empty
  const std::size_t pieces = convex_.pieces[i];
  for (std::size_t q = 0; q < erp::ConvexFaces::max_pieces; ++q) {
    TriangleForces& f = forces[max_faces3 + q];
    f.triangle[i] = q < pieces ? convex_.seed[q][i] : -1;
    f.bary[i] = q < pieces ? convex_.bary[q][i] : Vec3::Zero();
    f.f[i] = q < pieces ? Vec3(-V * shares[max_faces3 + q]) : Vec3::Zero();
  }
}

// f_wall = rho V (nu R <lap v>_i' + the approach viscosity) on face k (eq. 52's viscous part).
void SpaceWallTerms::record_viscous(std::size_t i, std::size_t k, const Vec3& f,
                                    WallForces3& forces) const {
  TriangleForces& slot = forces[viscous_slot3 + k];
  const int t = hits_[k].triangle[i];
  slot.triangle[i] = t;
  slot.bary[i] = t >= 0 ? hits_[k].bary[i] : Vec3::Zero();
  slot.f[i] = t >= 0 ? f : Vec3::Zero();
}

} // namespace fsi::emps
