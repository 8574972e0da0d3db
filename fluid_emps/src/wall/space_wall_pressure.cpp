// The wall part of the pressure gradient in 3-D over the faces acting on a particle.
#include "fluid_emps/space_wall_terms.hpp"

namespace fsi::emps {

// Beside convex edges and corners the pieces' term replaces the mirrors of the faces that seed
// them (convex_part), and the images behind two or three walls are over the other faces.
void SpaceWallTerms::add_pressure(std::size_t i, double dt, Vec3& grad,
                                  std::array<Vec3, max_faces3>& per_face) const {
  const ConvexPart part = convex_part(i);
  const Vec3 corner = corner_mirror_pressure(i, part.replaced);
  grad += corner;
  per_face = split_corner_term(corner, hits_, i);
  for (std::size_t k = 0; k < max_faces3; ++k) {
    if (hits_[k].triangle[i] < 0) continue;
    const Vec3 mirror = part.replaced >> k & 1u ? Vec3::Zero() : mirror_pressure(i, k);
    const Vec3 face = mirror + contact(i, k, dt);
    grad += face;
    per_face[k] += face;
  }
  const Vec3 convex = convex_pressure(i, part);
  grad += convex;
  per_face[part.owner] += convex;
}

} // namespace fsi::emps
