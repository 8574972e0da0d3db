// The solid's wedge beside a convex edge or corner in 3-D (the 2-D convex_corners carried over to
// triangle walls): the lattice that replaces face 0's half-space in eqs. 20 and 25.
#include "fluid_emps/space_wall_terms.hpp"

#include <algorithm>
#include <numbers>

namespace fsi::emps {

// Face 0's solid is the intersection of its half-space with its convex faces' (ConvexFaces), in
// front of the other acting faces (their lattice is counted by their own z, mirrors and images):
// region_lattice_sum3 counts that lattice, exact on the lattice for a box's right angles. share:
// the product over the convex faces of min(turn / 90 degrees, 1), as 2-D's; 0 without a convex
// face or where the region is not a box's.
SpaceWallTerms::ConvexPart SpaceWallTerms::convex_part(std::size_t i) const {
  ConvexPart part;
  const std::size_t count = convex_.count[i];
  if (count == 0) return part;
  std::array<erp::HalfSpace3, erp::ConvexFaces::max_planes + max_faces3 - 1> region;
  std::size_t m = 0;
  double share = 1.0;
  for (std::size_t k = 0; k <= count; ++k) {
    region[m++] = {convex_.n[k][i], convex_.s[k][i]};
    if (k > 0) share *= std::min(turn_share(convex_.n[0][i], convex_.n[k][i]), 1.0);
  }
  for (std::size_t k = 1; k < max_faces3; ++k)
    if (hits_[k].triangle[i] >= 0) region[m++] = {-hits_[k].n_wall[i], -hits_[k].r[i]};
  const auto lattice = erp::region_lattice_sum3(std::span(region.data(), m), l0_, r_e_, w_e_);
  if (!lattice) return part;
  return {share, *lattice};
}

} // namespace fsi::emps
