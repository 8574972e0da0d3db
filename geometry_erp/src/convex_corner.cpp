#include "geometry_erp/convex_corner.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace fsi::erp {

double concave_overlap(const Vec2& n1, const Vec2& n2, double r1, double r2, double l0, double r_e,
                       const WeightFunction& w) {
  const double cos_turn = std::clamp(n1.dot(n2), -1.0, 1.0);
  const double share = std::acos(cos_turn) / (0.5 * std::numbers::pi);
  return share * corner_weight_sum(r1, r2, l0, r_e, w);
}

ConvexPart convex_part(const WallSet& walls, int segment, double t, const Vec2& x, double r,
                       const Vec2& n_face, const WallWeightTable& z, double l0, double r_e,
                       const WeightFunction& w) {
  const auto& ends = walls.segments().node[static_cast<std::size_t>(segment)];
  ConvexPart part;
  for (int end = 0; end < 2; ++end) {
    const int L = ends[static_cast<std::size_t>(end)];
    const Vec2 from_vertex = x - walls.nodes().x[static_cast<std::size_t>(L)];
    if (from_vertex.squaredNorm() >= r_e * r_e) continue;
    const auto joint = walls.convex_joint(L);
    if (!joint) continue;
    const double share = std::min(joint->turn / (0.5 * std::numbers::pi), 1.0);
    if (t == static_cast<double>(end)) { // the vertex is the nearest point
      const double a = std::max(from_vertex.dot(joint->n_in), 0.0);
      const double b = std::max(from_vertex.dot(joint->n_out), 0.0);
      const Vec2 g = corner_gradient_sum(a, b, l0, r_e, w);
      return {share * (corner_weight_sum(a, b, l0, r_e, w) - z(r)), share,
              -(g.x() * joint->n_in + g.y() * joint->n_out)};
    }
    if (t == 0.0 || t == 1.0) continue; // the other end is nearest
    const Vec2& n_other = segment == joint->in_segment ? joint->n_out : joint->n_in;
    const double h = -from_vertex.dot(n_other);
    if (h <= 0.0) continue;
    if (part.share == 0.0) part.g = -wall_gradient_sum(r, l0, r_e, w) * n_face;
    const Vec2 g = corner_gradient_sum(r, h, l0, r_e, w); // points at -n_face, +n_other
    part.dz -= share * corner_weight_sum(r, h, l0, r_e, w);
    part.g -= share * (g.y() * n_other - g.x() * n_face);
    part.share = std::max(part.share, share);
  }
  return part;
}

} // namespace fsi::erp
