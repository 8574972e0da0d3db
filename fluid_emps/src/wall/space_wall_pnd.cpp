// The wall part of pnd (eq. 20) over the triangle faces that act on a particle (3-D).
#include "fluid_emps/space_wall_terms.hpp"

#include <algorithm>

namespace fsi::emps {

// z(r_k) of every face, the lattice behind two faces (edge_weight_sum3) taken off once per pair
// and the lattice behind all three (corner_weight_sum3) added back once (inclusion-exclusion,
// exact on the lattice at right angles; another turn scales each overlap by its turn's share of a
// right angle, the corner's by the product of the three).
double SpaceWallTerms::faces_weight(std::size_t i, const std::array<std::size_t, max_faces3>& on,
                                    std::size_t faces) const {
  const auto r = [&](std::size_t k) { return hits_[on[k]].r[i]; };
  const auto n = [&](std::size_t k) -> const Vec3& { return hits_[on[k]].n_wall[i]; };
  double z = 0.0;
  for (std::size_t k = 0; k < faces; ++k) z += z_(r(k));
  for (std::size_t k = 1; k < faces; ++k)
    for (std::size_t l = 0; l < k; ++l)
      z -= turn_share(n(l), n(k)) * erp::edge_weight_sum3(r(l), r(k), l0_, r_e_, w_e_);
  if (faces == 3)
    z += turn_share(n(0), n(1)) * turn_share(n(0), n(2)) * turn_share(n(1), n(2)) *
         erp::corner_weight_sum3(r(0), r(1), r(2), l0_, r_e_, w_e_);
  return z;
}

// n*_i = sum_j w_ij + z (eqs. 9, 20), z over the acting faces (faces_weight). With convex_corners
// beside a convex edge or corner the faces seeding a convex piece give way to the pieces' lattice
// in front of the others (convex_part): z = z_others + that lattice's weight.
// WallDensity::scaled counts z compressed like the fluid beside it, z max(1, n_i / (n0 - z)).
double SpaceWallTerms::pnd(std::size_t i, double fluid_pnd) const {
  const ConvexPart part = convex_part(i);
  std::array<std::size_t, max_faces3> on{};
  const std::size_t faces = acting_faces(i, on, part.replaced);
  const double z = faces_weight(i, on, faces) + part.lattice.weight;
  if (o_.pnd.density == WallDensity::added) return fluid_pnd + z;
  return fluid_pnd + z * std::max(1.0, fluid_pnd / std::max(n0_ - z, 0.25 * n0_));
}

} // namespace fsi::emps
