#pragma once
// Shared by the locator back-ends: distance to one segment and the hit record of eqs. 18-19.
#include "geometry_erp/segment_geometry.hpp"
#include "geometry_erp/wall_locator.hpp"

#include "fsi/core/parallel.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fsi::erp::detail {

/// Best segment so far for one particle; d2 starts at r_e^2 so only walls within r_e count.
struct Nearest {
  int segment = -1;
  double t = 0.0;
  double d2;
};

inline SegmentGeometry segment_geometry(const WallSet& walls, int s) {
  const auto& [a, b] = walls.segments().node[static_cast<std::size_t>(s)];
  const Vec2& xa = walls.nodes().x[static_cast<std::size_t>(a)];
  const Vec2& xb = walls.nodes().x[static_cast<std::size_t>(b)];
  const Vec2 ab = xb - xa;
  const double length2 = ab.dot(ab);
  return {xa, xb, ab, length2, 1.0 / length2, s};
}

/// Nearest point of a segment to p; replaces `best` if strictly nearer, or equally near with a
/// lower segment index. The projection is compared with |ab|^2 before scaling, so a particle on
/// node b gets t = 1 exactly (p - a and ab are then the same numbers), and on node a t = 0.
/// The update is written as selects (conditional moves): which candidate wins is unpredictable.
inline void consider_segment(const SegmentGeometry& g, const Vec2& p, Nearest& best) {
  const double along = (p - g.a).dot(g.ab);
  const double t = along >= g.length2 ? 1.0 : std::max(along * g.inv_length2, 0.0);
  const double d2 = (p - (g.a + t * g.ab)).squaredNorm();
  const bool nearer = d2 < best.d2 || (d2 == best.d2 && g.id < best.segment);
  best.segment = nearer ? g.id : best.segment;
  best.t = nearer ? t : best.t;
  best.d2 = nearer ? d2 : best.d2;
}

/// Second-face candidate (wall_locator.hpp): nearest point strictly inside the segment, particle
/// on its fluid (left) side, normal turned by more than 30 degrees from n1, not segment s1.
inline void consider_face(const SegmentGeometry& g, const Vec2& p, const Vec2& n1, int s1,
                          Nearest& best) {
  if (g.id == s1) return;
  const double along = (p - g.a).dot(g.ab);
  if (along <= 0.0 || along >= g.length2) return;
  const double t = along * g.inv_length2;
  const Vec2 d = p - (g.a + t * g.ab);
  const double d2 = d.squaredNorm();
  if (!(d2 < best.d2 || (d2 == best.d2 && g.id < best.segment))) return;
  const double side = g.ab.x() * d.y() - g.ab.y() * d.x(); // (b - a) x d > 0: fluid side
  if (side <= 0.0 || d.dot(n1) > second_face_max_cos * std::sqrt(d2)) return;
  best = {g.id, t, d2};
}

/// Writes particle i's second-face record.
inline void write_second(const WallSet& walls, const Vec2& p, const Nearest& face, WallHits& hits,
                         std::size_t i) {
  hits.segment2[i] = face.segment;
  if (face.segment < 0) return;
  const auto& [a, b] = walls.segments().node[static_cast<std::size_t>(face.segment)];
  const auto ua = static_cast<std::size_t>(a), ub = static_cast<std::size_t>(b);
  const Vec2 x_wall = walls.nodes().x[ua] + face.t * (walls.nodes().x[ub] - walls.nodes().x[ua]);
  const double r = std::sqrt(face.d2);
  hits.t2[i] = face.t;
  hits.r2[i] = r;
  hits.x_wall2[i] = x_wall;
  hits.n_wall2[i] = (p - x_wall) / r;
  hits.v_wall2[i] = (1.0 - face.t) * walls.nodes().v[ua] + face.t * walls.nodes().v[ub];
}

/// Writes particle i's record from its nearest segment (see wall_locator.hpp for the rules).
inline void write_hit(const WallSet& walls, double r_e, const Vec2& p, const Nearest& best,
                      WallHits& hits, std::size_t i) {
  hits.segment[i] = best.segment;
  if (best.segment < 0) {
    hits.r[i] = std::numeric_limits<double>::infinity();
    hits.crossed[i] = 0;
    return;
  }
  const auto& [a, b] = walls.segments().node[static_cast<std::size_t>(best.segment)];
  const auto ua = static_cast<std::size_t>(a), ub = static_cast<std::size_t>(b);
  const double t = best.t;
  const Vec2 x_wall =
      t == 1.0 ? walls.nodes().x[ub]
               : Vec2(walls.nodes().x[ua] + t * (walls.nodes().x[ub] - walls.nodes().x[ua]));
  const Vec2 n_fluid = t == 0.0   ? walls.node_normal(a, best.segment)
                       : t == 1.0 ? walls.node_normal(b, best.segment)
                                  : walls.segment_normal(best.segment);
  const double r = (p - x_wall).norm();
  hits.t[i] = t;
  hits.r[i] = r;
  hits.x_wall[i] = x_wall;
  if (r <= on_wall_tolerance * r_e) {
    hits.n_wall[i] = n_fluid;
    hits.crossed[i] = 0;
  } else {
    hits.n_wall[i] = (p - x_wall) / r; // eq. 19
    const bool free_end = (t == 0.0 && walls.open_end(a)) || (t == 1.0 && walls.open_end(b));
    hits.crossed[i] = !free_end && hits.n_wall[i].dot(n_fluid) < 0.0 ? 1 : 0;
  }
  hits.v_wall[i] = (1.0 - t) * walls.nodes().v[ua] + t * walls.nodes().v[ub];
  hits.a_wall[i] = (1.0 - t) * walls.nodes().a[ua] + t * walls.nodes().a[ub];
}

/// For every particle in parallel: visit(p, bound, consider) calls consider(segment geometry) for
/// every segment that may lie within sqrt(bound) of p (bound shrinks as consider finds nearer
/// ones). Writes the nearest-wall record and, if asked, the second face.
template <class Point, class Visit>
void batch_query(const WallSet& walls, double r_e, bool second_face, std::size_t n, Point&& point,
                 Visit&& visit, WallHits& hits) {
  hits.resize(n);
  parallel_for_balanced(n, [&](std::size_t i) {
    const Vec2 p = point(i);
    Nearest best{-1, 0.0, r_e * r_e};
    visit(p, best.d2, [&](const SegmentGeometry& g) { consider_segment(g, p, best); });
    write_hit(walls, r_e, p, best, hits, i);
    hits.segment2[i] = -1;
    if (!second_face || best.segment < 0) return;
    Nearest face{-1, 0.0, r_e * r_e};
    const Vec2 n1 = hits.n_wall[i];
    visit(p, face.d2,
          [&](const SegmentGeometry& g) { consider_face(g, p, n1, best.segment, face); });
    write_second(walls, p, face, hits, i);
  });
}

} // namespace fsi::erp::detail
