#pragma once
// Wall corners in the ERP wall terms: the lattice a concave corner's two faces both count, and
// the wedge that replaces the half-plane of eqs. 20 and 25 beside a convex corner.
#include "fsi/core/types.hpp"
#include "geometry_erp/wall_set.hpp"
#include "geometry_erp/wall_weight.hpp"

namespace fsi::erp {

/// The virtual lattice both faces of a concave corner count, counted once: exact for a right
/// angle (corner_weight_sum at the distances r1, r2 from the faces), scaled by the angle between
/// the faces' normals n1, n2 otherwise.
double concave_overlap(const Vec2& n1, const Vec2& n2, double r1, double r2, double l0, double r_e,
                       const WeightFunction& w);

/// A convex corner's part of a particle's wall terms: the pnd correction dz (to add to z(r)),
/// and the solid's lattice sum g of eq. 10 that replaces the mirror's in proportion `share`.
struct ConvexPart {
  double dz = 0.0, share = 0.0;
  Vec2 g = Vec2::Zero();
};

/// The solid at a convex corner is a wedge, not the half-plane that z(r) and the mirror of the
/// nearest face or vertex assume (eqs. 20, 25). For a particle at x whose nearest wall point is
/// at local coordinate t on `segment` (distance r, fluid normal n_face), for each convex end of
/// the segment within r_e: next to the vertex (the vertex nearest) the solid is the wedge's
/// lattice, at distances from the two face lines; next to a face it is the half-plane less the
/// quadrant beyond each convex end's other face (depth h behind it). pnd counts that lattice
/// instead of z, and the wall's pressure term is that lattice's eq. 10 sum with p_i' = p_i
/// (eq. 26). Exact on the lattice at a right angle; a turn below 90 degrees mixes with the
/// half-plane in proportion turn / 90 degrees.
ConvexPart convex_part(const WallSet& walls, int segment, double t, const Vec2& x, double r,
                       const Vec2& n_face, const WallWeightTable& z, double l0, double r_e,
                       const WeightFunction& w);

} // namespace fsi::erp
