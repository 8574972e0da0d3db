// The wall part of the pressure gradient in 3-D over the faces acting on a particle.
#include "fluid_emps/space_wall_terms.hpp"

namespace fsi::emps {

// Beside convex edges and corners the pieces' term replaces the mirrors of the faces that seed
// them (convex_part), and the images behind two or three walls are over the other faces. The
// pieces' term enters grad whole (as without the shares), each piece's share in its slot.
void SpaceWallTerms::add_pressure(std::size_t i, double dt, Vec3& grad, WallShares3& shares) const {
  const ConvexPart part = convex_part(i);
  const Vec3 corner = corner_mirror_pressure(i, part.replaced);
  grad += corner;
  const std::array<Vec3, max_faces3> split = split_corner_term(corner, hits_, i);
  for (std::size_t k = 0; k < max_faces3; ++k) {
    shares[k] = split[k];
    if (hits_[k].triangle[i] < 0) continue;
    const Vec3 mirror = part.replaced >> k & 1u ? Vec3::Zero() : mirror_pressure(i, k);
    const Vec3 face = mirror + contact(i, k, dt);
    grad += face;
    shares[k] += face;
  }
  grad += convex_pressure(i, part);
  for (std::size_t q = 0; q < erp::ConvexFaces::max_pieces; ++q)
    shares[max_faces3 + q] = piece_pressure(i, part, q);
}

} // namespace fsi::emps
