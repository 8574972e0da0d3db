#pragma once
// The nearest triangle (closest point: fsi/core/closest_on_triangle.hpp) and the hit record of
// eqs. 18-19 for TriangleLocator.
#include "fsi/core/closest_on_triangle.hpp"
#include "geometry_erp/triangle_locator.hpp"
#include "geometry_erp/wall_locator.hpp"

#include <cmath>
#include <limits>

namespace fsi::erp::detail {

/// Best triangle so far for one particle; d2 starts at r_e^2 so only walls within r_e count.
struct NearestTriangle {
  int triangle = -1;
  TrianglePoint point{0.0, 0.0, TriangleFeature::face};
  double d2;
};

/// Replaces `best` if g is strictly nearer, or equally near with a lower index.
inline void consider_triangle(const TriangleGeometry& g, const Vec3& p, NearestTriangle& best) {
  const TrianglePoint q = closest_on_triangle(p, g.a, g.b, g.c);
  const double d2 = (p - triangle_point(q, g.a, g.b, g.c)).squaredNorm();
  if (d2 < best.d2 || (d2 == best.d2 && g.id < best.triangle)) best = {g.id, q, d2};
}

/// Writes particle i's record from its nearest triangle (see triangle_locator.hpp for the rules).
inline void write_triangle_hit(const TriangleWallSet& walls, double r_e, const Vec3& p,
                               const NearestTriangle& best, TriangleHits& hits, std::size_t i) {
  hits.triangle[i] = best.triangle;
  if (best.triangle < 0) {
    hits.r[i] = std::numeric_limits<double>::infinity();
    hits.crossed[i] = 0;
    return;
  }
  const auto& abc = walls.triangles().node[static_cast<std::size_t>(best.triangle)];
  const auto& nodes = walls.nodes();
  const auto ua = static_cast<std::size_t>(abc[0]), ub = static_cast<std::size_t>(abc[1]),
             uc = static_cast<std::size_t>(abc[2]);
  const TrianglePoint& q = best.point;
  const Vec3 x_wall = triangle_point(q, nodes.x[ua], nodes.x[ub], nodes.x[uc]);
  const Vec3 bary(1.0 - q.v - q.w, q.v, q.w);
  const Vec3 n_fluid = walls.pseudo_normal(best.triangle, q.feature);
  const double r = (p - x_wall).norm();
  hits.feature[i] = q.feature;
  hits.bary[i] = bary;
  hits.r[i] = r;
  hits.x_wall[i] = x_wall;
  if (r <= on_wall_tolerance * r_e) {
    hits.n_wall[i] = n_fluid;
    hits.crossed[i] = 0;
  } else {
    hits.n_wall[i] = (p - x_wall) / r; // eq. 19
    const bool border = walls.open(best.triangle, q.feature);
    hits.crossed[i] = !border && hits.n_wall[i].dot(n_fluid) < 0.0 ? 1 : 0;
  }
  hits.v_wall[i] = bary[0] * nodes.v[ua] + bary[1] * nodes.v[ub] + bary[2] * nodes.v[uc];
  hits.a_wall[i] = bary[0] * nodes.a[ua] + bary[1] * nodes.a[ub] + bary[2] * nodes.a[uc];
}

} // namespace fsi::erp::detail
