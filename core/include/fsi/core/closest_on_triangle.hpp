#pragma once
// The point of a triangle nearest to a point (Ericson, Real-Time Collision Detection, sec. 5.1.5),
// with the feature it lies on: the one copy for the ERP triangle walls (geometry_erp) and the SPH
// fluid's 3-D interface boundary (fluid_sph).
#include "fsi/core/types.hpp"

namespace fsi {

/// The feature of a triangle a nearest point lies on: a vertex, an edge (edge k joins vertex k
/// and vertex k + 1 mod 3: ab, bc, ca) or the face's interior.
enum class TriangleFeature : unsigned char {
  vertex_a,
  vertex_b,
  vertex_c,
  edge_ab,
  edge_bc,
  edge_ca,
  face
};

/// Nearest point of triangle abc: barycentric (v, w) on b and c, and its feature.
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

} // namespace fsi
