#pragma once
// Shared by the locator back-ends: distance to one segment and the hit record of eqs. 18-19.
#include "geometry_erp/segment_geometry.hpp"
#include "geometry_erp/wall_locator.hpp"

#include "fsi/core/parallel.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>

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

/// Corner-face candidate (wall_locator.hpp): nearest point strictly inside the segment, particle
/// on its fluid (left) side, not one of the faces found before (segments `earlier`, normals
/// `n_earlier`), its normal turned by more than 30 degrees from each of theirs.
inline void consider_face(const SegmentGeometry& g, const Vec2& p, std::span<const int> earlier,
                          std::span<const Vec2> n_earlier, Nearest& best) {
  if (std::find(earlier.begin(), earlier.end(), g.id) != earlier.end()) return;
  const double along = (p - g.a).dot(g.ab);
  if (along <= 0.0 || along >= g.length2) return;
  const double t = along * g.inv_length2;
  const Vec2 d = p - (g.a + t * g.ab);
  const double d2 = d.squaredNorm();
  if (!(d2 < best.d2 || (d2 == best.d2 && g.id < best.segment))) return;
  const double side = g.ab.x() * d.y() - g.ab.y() * d.x(); // (b - a) x d > 0: fluid side
  if (side <= 0.0) return;
  for (const Vec2& n : n_earlier)
    if (d.dot(n) > corner_face_max_cos * std::sqrt(d2)) return;
  best = {g.id, t, d2};
}

/// Writes particle i's record of a corner face.
inline void write_face(const WallSet& walls, const Vec2& p, const Nearest& face, FaceHits& hits,
                       std::size_t i) {
  hits.segment[i] = face.segment;
  const auto& [a, b] = walls.segments().node[static_cast<std::size_t>(face.segment)];
  const auto ua = static_cast<std::size_t>(a), ub = static_cast<std::size_t>(b);
  const Vec2 x_wall = walls.nodes().x[ua] + face.t * (walls.nodes().x[ub] - walls.nodes().x[ua]);
  const double r = std::sqrt(face.d2);
  hits.t[i] = face.t;
  hits.r[i] = r;
  hits.x_wall[i] = x_wall;
  hits.n_wall[i] = (p - x_wall) / r;
  hits.v_wall[i] = (1.0 - face.t) * walls.nodes().v[ua] + face.t * walls.nodes().v[ub];
}

/// Writes particle i's record from its nearest segment (see wall_locator.hpp for the rules).
inline void write_hit(const WallSet& walls, double r_e, const Vec2& p, const Nearest& best,
                      WallHits& hits, std::size_t i) {
  FaceHits& h = hits.face[0];
  h.segment[i] = best.segment;
  if (best.segment < 0) {
    h.r[i] = std::numeric_limits<double>::infinity();
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
  h.t[i] = t;
  h.r[i] = r;
  h.x_wall[i] = x_wall;
  if (r <= on_wall_tolerance * r_e) {
    h.n_wall[i] = n_fluid;
    hits.crossed[i] = 0;
  } else {
    h.n_wall[i] = (p - x_wall) / r; // eq. 19
    const bool free_end = (t == 0.0 && walls.open_end(a)) || (t == 1.0 && walls.open_end(b));
    hits.crossed[i] = !free_end && h.n_wall[i].dot(n_fluid) < 0.0 ? 1 : 0;
  }
  h.v_wall[i] = (1.0 - t) * walls.nodes().v[ua] + t * walls.nodes().v[ub];
  hits.a_wall[i] = (1.0 - t) * walls.nodes().a[ua] + t * walls.nodes().a[ub];
}

/// For every particle in parallel: visit(p, bound, consider) calls consider(segment geometry) for
/// every segment that may lie within sqrt(bound) of p (bound shrinks as consider finds nearer
/// ones). Writes the nearest-wall record and, if asked, the corner faces.
template <class Point, class Visit>
void batch_query(const WallSet& walls, double r_e, bool corner_faces, std::size_t n, Point&& point,
                 Visit&& visit, WallHits& hits) {
  hits.resize(n);
  parallel_for_balanced(n, [&](std::size_t i) {
    const Vec2 p = point(i);
    Nearest best{-1, 0.0, r_e * r_e};
    visit(p, best.d2, [&](const SegmentGeometry& g) { consider_segment(g, p, best); });
    write_hit(walls, r_e, p, best, hits, i);
    for (std::size_t k = 1; k < max_faces; ++k) hits.face[k].segment[i] = -1;
    if (!corner_faces || best.segment < 0) return;
    std::array<int, max_faces> segments{best.segment};
    std::array<Vec2, max_faces> normals{hits.face[0].n_wall[i]};
    for (std::size_t k = 1; k < max_faces; ++k) {
      Nearest face{-1, 0.0, r_e * r_e};
      visit(p, face.d2, [&](const SegmentGeometry& g) {
        consider_face(g, p, std::span(segments).first(k), std::span(normals).first(k), face);
      });
      if (face.segment < 0) return;
      write_face(walls, p, face, hits.face[k], i);
      segments[k] = face.segment;
      normals[k] = hits.face[k].n_wall[i];
    }
  });
}

} // namespace fsi::erp::detail
