// The convex faces of TriangleLocator: the other planes of a convex edge or corner.
#include "fsi/core/closest_on_triangle.hpp"
#include "geometry_erp/triangle_locator.hpp"
#include "geometry_erp/wall_locator.hpp"

#include "fsi/core/fresh_resize.hpp"
#include "fsi/core/parallel.hpp"

#include <algorithm>
#include <cmath>

namespace fsi::erp {

void ConvexFaces::resize(std::size_t n_points) {
  fresh_resize(pieces, n_points);
  for (std::size_t q = 0; q < max_pieces; ++q) {
    fresh_resize(face[q], n_points);
    fresh_resize(seed[q], n_points);
    fresh_resize(bary[q], n_points);
    fresh_resize(end[q], n_points);
  }
  for (std::size_t k = 0; k < max_planes; ++k) {
    fresh_resize(n[k], n_points);
    fresh_resize(s[k], n_points);
  }
}

namespace {
/// Every corner of g on or behind the plane through x with normal n (to `tol`).
bool behind_plane(const TriangleGeometry& g, const Vec3& x, const Vec3& n, double tol) {
  return (g.a - x).dot(n) <= tol && (g.b - x).dot(n) <= tol && (g.c - x).dot(n) <= tol;
}

/// g (normal n) is a convex face of g0 (normal n0): it turns by more than 30 degrees, lies behind
/// g0's plane and g0 behind its own.
bool convex_pair(const TriangleGeometry& g0, const Vec3& n0, const TriangleGeometry& g,
                 const Vec3& n, double tol) {
  return n0.dot(n) < corner_face_max_cos && behind_plane(g, g0.a, n0, tol) &&
         behind_plane(g0, g.a, n, tol);
}

/// Every corner of g on or in front of the plane through x with normal n (to `tol`).
bool before_plane(const TriangleGeometry& g, const Vec3& x, const Vec3& n, double tol) {
  return (g.a - x).dot(n) >= -tol && (g.b - x).dot(n) >= -tol && (g.c - x).dot(n) >= -tol;
}

/// n turns by more than 30 degrees from each of `normals`.
bool turned(const Vec3& n, std::span<const Vec3> normals) {
  return std::all_of(normals.begin(), normals.end(),
                     [&](const Vec3& m) { return m.dot(n) < corner_face_max_cos; });
}
} // namespace

bool TriangleLocator::find_convex_edge() const {
  // convex_faces pairs the nearest triangle with triangles within r_e of the same point: boxes
  // within 2 r_e of each other, listed by the cells overlapping the grown box.
  const double tol = on_wall_tolerance * r_e_;
  const Vec3 reach = Vec3::Constant(2.0 * r_e_);
  std::vector<int> near;
  for (std::size_t t = 0; t < boxes_.size(); ++t) {
    grid_.overlapping(boxes_[t].lo - reach, boxes_[t].hi + reach, near);
    const TriangleGeometry g0 = geometry(t);
    const Vec3& n0 = walls_->face_normal(g0.id);
    for (const int q : near)
      if (q != g0.id &&
          convex_pair(g0, n0, geometry(static_cast<std::size_t>(q)), walls_->face_normal(q), tol))
        return true;
  }
  return false;
}

std::size_t TriangleLocator::convex_piece(const Vec3& p, int t0, ConvexFaces& convex, std::size_t i,
                                          std::size_t m) const {
  const double tol = on_wall_tolerance * r_e_;
  const TriangleGeometry g0 = geometry(static_cast<std::size_t>(t0));
  std::array<Vec3, ConvexFaces::max_planes> normals;
  normals[0] = walls_->face_normal(t0);
  convex.n[m][i] = normals[0];
  convex.s[m][i] = (p - g0.a).dot(normals[0]);
  std::size_t count = 1;
  while (m + count < ConvexFaces::max_planes) {
    double best = r_e_ * r_e_;
    int best_id = -1;
    Vec3 best_a = Vec3::Zero();
    for_each_near(p, [&](const TriangleGeometry& g) {
      const Vec3& nt = walls_->face_normal(g.id);
      if (!turned(nt, std::span<const Vec3>(normals.data(), count)) ||
          !convex_pair(g0, normals[0], g, nt, tol))
        return;
      const double d2 =
          (p - triangle_point(closest_on_triangle(p, g.a, g.b, g.c), g.a, g.b, g.c)).squaredNorm();
      if (d2 < best || (d2 == best && best_id >= 0 && g.id < best_id))
        best = d2, best_id = g.id, best_a = g.a;
    });
    if (best_id < 0) break;
    normals[count] = walls_->face_normal(best_id);
    convex.n[m + count][i] = normals[count];
    convex.s[m + count][i] = (p - best_a).dot(normals[count]);
    ++count;
  }
  return m + count;
}

void TriangleLocator::convex_faces(std::span<const double> x, std::span<const double> y,
                                   std::span<const double> z, std::span<const TriangleHits> faces,
                                   ConvexFaces& convex) const {
  const std::size_t n = x.size();
  convex.resize(n);
  if (!has_convex_edges_) { // no pair of triangles to take: no convex face anywhere
    std::fill(convex.pieces.begin(), convex.pieces.end(), 0);
    return;
  }
  const double tol = on_wall_tolerance * r_e_;
  const auto& nodes = walls_->nodes().x;
  parallel_for_balanced(n, [&](std::size_t i) {
    convex.pieces[i] = 0;
    if (faces[0].triangle[i] < 0) return;
    const Vec3 p(x[i], y[i], z[i]);
    // The acting faces' planes (a node and the normal), each a seed.
    std::array<Vec3, 3> acting_x, acting_n;
    std::size_t acting = 0, m = 0, q = 0;
    const auto add_piece = [&](int face, int seed, const Vec3& bary, std::size_t end) {
      convex.face[q][i] = static_cast<signed char>(face);
      convex.seed[q][i] = seed;
      convex.bary[q][i] = bary;
      convex.end[q][i] = static_cast<unsigned char>(end);
      ++q, m = end;
    };
    for (std::size_t k = 0; k < faces.size() && acting < acting_n.size(); ++k) {
      const int t = faces[k].triangle[i];
      if (t < 0) continue;
      acting_x[acting] =
          nodes[static_cast<std::size_t>(walls_->triangles().node[static_cast<std::size_t>(t)][0])];
      acting_n[acting++] = walls_->face_normal(t);
      const std::size_t end = convex_piece(p, t, convex, i, m);
      if (end > m + 1 && q < ConvexFaces::max_pieces)
        add_piece(static_cast<int>(k), t, faces[k].bary[i], end);
    }
    // Seeds of their own: the solids standing on the acting faces.
    while (q < ConvexFaces::max_pieces && m + 1 < ConvexFaces::max_planes) {
      double best = r_e_ * r_e_;
      int best_id = -1;
      Vec3 best_bary = Vec3::Zero();
      for_each_near(p, [&](const TriangleGeometry& g) {
        const Vec3& nt = walls_->face_normal(g.id);
        if ((p - g.a).dot(nt) <= tol || !turned(nt, std::span<const Vec3>(acting_n.data(), acting)))
          return;
        for (std::size_t k = 0; k < m; ++k)
          if (convex.n[k][i].dot(nt) >= corner_face_max_cos) return;
        for (std::size_t k = 0; k < acting; ++k)
          if (!before_plane(g, acting_x[k], acting_n[k], tol)) return;
        const TrianglePoint foot = closest_on_triangle(p, g.a, g.b, g.c);
        const double d2 = (p - triangle_point(foot, g.a, g.b, g.c)).squaredNorm();
        if (d2 < best || (d2 == best && best_id >= 0 && g.id < best_id))
          best = d2, best_id = g.id, best_bary = Vec3(1.0 - foot.v - foot.w, foot.v, foot.w);
      });
      if (best_id < 0) break;
      const std::size_t end = convex_piece(p, best_id, convex, i, m);
      if (end == m + 1) break;
      add_piece(-1, best_id, best_bary, end);
    }
    convex.pieces[i] = static_cast<unsigned char>(q);
  });
}

} // namespace fsi::erp
