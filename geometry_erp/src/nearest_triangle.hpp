#pragma once
// Closest point of a triangle (Ericson, Real-Time Collision Detection, sec. 5.1.5) and the hit
// record of eqs. 18-19 for TriangleLocator.
#include "geometry_erp/triangle_locator.hpp"
#include "geometry_erp/wall_locator.hpp"

#include <cmath>
#include <limits>

namespace fsi::erp::detail {

/// Nearest point of triangle abc to p: barycentric (v, w) on b and c, and its feature.
struct TrianglePoint {
  double v, w;
  TriangleFeature feature;
};

/// Ericson's Voronoi-region walk: vertex regions give the vertex exactly, edge regions a point on
/// the edge, else the projection onto the face.
inline TrianglePoint closest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b,
                                         const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return {0.0, 0.0, TriangleFeature::vertex_a};
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return {1.0, 0.0, TriangleFeature::vertex_b};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return {d1 / (d1 - d3), 0.0, TriangleFeature::edge_ab};
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return {0.0, 1.0, TriangleFeature::vertex_c};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return {0.0, d2 / (d2 - d6), TriangleFeature::edge_ca};
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {1.0 - w, w, TriangleFeature::edge_bc};
  }
  const double denom = 1.0 / (va + vb + vc);
  return {vb * denom, vc * denom, TriangleFeature::face};
}

/// The point of abc at barycentric (1 - v - w, v, w); vertices exactly.
inline Vec3 triangle_point(const TrianglePoint& q, const Vec3& a, const Vec3& b, const Vec3& c) {
  switch (q.feature) {
  case TriangleFeature::vertex_a:
    return a;
  case TriangleFeature::vertex_b:
    return b;
  case TriangleFeature::vertex_c:
    return c;
  case TriangleFeature::edge_bc:
    return b + q.w * (c - b);
  default:
    return a + q.v * (b - a) + q.w * (c - a);
  }
}

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
