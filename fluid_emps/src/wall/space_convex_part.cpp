// The solid's convex pieces beside a convex edge or corner in 3-D (the 2-D convex_corners carried
// over to triangle walls): the lattice that replaces their seeds' half-spaces in eqs. 20 and 25.
#include "fluid_emps/space_wall_terms.hpp"

#include <bit>

namespace fsi::emps {

namespace {

/// The half-space {n, s} seen from x_i reflected across a face's plane (unit normal m, x_i at
/// distance r in front): y lies in the image iff its reflection y - 2 ((y - x_i).m + r) m lies in
/// {n, s}, i.e. (y - x_i).(n - 2 (m.n) m) < -(s - 2 r (m.n)).
erp::HalfSpace3 reflected(const erp::HalfSpace3& h, const Vec3& m, double r) {
  const double c = m.dot(h.n);
  return {h.n - 2.0 * c * m, h.s - 2.0 * r * c};
}

} // namespace

// The solid is the union of the other acting faces' half-spaces H and the pieces P_q
// (ConvexFaces), the lattice of P_1 u P_2 u ... in front of every H counted by inclusion-exclusion
// over the pieces, each intersection region_lattice_sum3's (exact on the lattice at right
// angles). The other faces' mirrors and images (eqs. 25-26) reflect the real fluid, which does not
// fill the pieces: what they miss is the pieces' lattice reflected across each other face, each
// pair and the three, added here as `images`, weighted as corner_mirror_pressure weighs its
// images (turn_share: 1 at right angles; planes that are not a box's make region_lattice_sum3
// refuse, and the part is empty: the faces' half-spaces as without convex_corners).
// The union's sum is not each piece's own sum added up where pieces overlap (two seeds of one
// solid): the term of a set of s pieces goes 1/s to each (ConvexPart::share). A point in t pieces
// then gives piece q sum over the sets S of them holding q of (-1)^(|S|+1)/|S| = 1/t (as
// C(t-1, s-1)/s = C(t, s)/t); disjoint pieces (other solids) have empty intersections, and each
// its own sum.
SpaceWallTerms::ConvexPart SpaceWallTerms::convex_part(std::size_t i) const {
  if (!o_.convex_corners || convex_.pieces[i] == 0) return {};
  const std::size_t pieces = convex_.pieces[i];
  ConvexPart part;
  for (std::size_t q = 0; q < pieces; ++q)
    if (convex_.face[q][i] >= 0) part.replaced |= 1u << convex_.face[q][i];
  std::array<std::size_t, max_faces3> on{};
  const std::size_t faces = acting_faces(i, on, part.replaced);
  constexpr std::size_t most = erp::ConvexFaces::max_planes + max_faces3;
  for (unsigned set = 1; set < 1u << pieces; ++set) {
    std::array<erp::HalfSpace3, most> region;
    std::size_t m = 0;
    for (std::size_t q = 0; q < pieces; ++q)
      if (set >> q & 1u)
        for (std::size_t k = convex_.begin(q, i); k < convex_.end[q][i]; ++k)
          region[m++] = {convex_.n[k][i], convex_.s[k][i]};
    for (std::size_t a = 0; a < faces; ++a)
      region[m++] = {-hits_[on[a]].n_wall[i], -hits_[on[a]].r[i]};
    const double sign = std::popcount(set) % 2 == 1 ? 1.0 : -1.0;
    const auto lattice = erp::region_lattice_sum3(std::span(region.data(), m), l0_, r_e_, w_e_);
    if (!lattice) return {};
    part.lattice.weight += sign * lattice->weight;
    part.lattice.gradient += sign * lattice->gradient;
    Vec3 images = Vec3::Zero(); // this set's images, for the pieces' shares
    for (unsigned across = 1; across < 1u << faces; ++across) {
      std::array<erp::HalfSpace3, most> image = region;
      double weight = 1.0;
      for (std::size_t a = 0; a < faces; ++a) {
        if (!(across >> a & 1u)) continue;
        const Vec3& n_a = hits_[on[a]].n_wall[i];
        for (std::size_t b = 0; b < a; ++b)
          if (across >> b & 1u) weight *= turn_share(hits_[on[b]].n_wall[i], n_a);
        for (std::size_t k = 0; k < m; ++k) image[k] = reflected(image[k], n_a, hits_[on[a]].r[i]);
      }
      const auto mirrored = erp::region_lattice_sum3(std::span(image.data(), m), l0_, r_e_, w_e_);
      if (!mirrored) return {};
      part.images += sign * weight * mirrored->gradient;
      images += weight * mirrored->gradient;
    }
    const Vec3 each = sign / std::popcount(set) * (lattice->gradient + images);
    for (std::size_t q = 0; q < pieces; ++q)
      if (set >> q & 1u) part.share[q] += each;
  }
  return part;
}

Vec3 SpaceWallTerms::convex_pressure(std::size_t i, const ConvexPart& part) const {
  return 3.0 / n0_ * ((2.0 * p_.p[i]) * (part.lattice.gradient + part.images));
}

Vec3 SpaceWallTerms::piece_pressure(std::size_t i, const ConvexPart& part, std::size_t q) const {
  return 3.0 / n0_ * ((2.0 * p_.p[i]) * part.share[q]);
}

} // namespace fsi::emps
