// The convex faces of TriangleLocator: the other planes of a convex edge or corner.
#include "fsi/core/closest_on_triangle.hpp"
#include "geometry_erp/triangle_locator.hpp"
#include "geometry_erp/wall_locator.hpp"

#include "fsi/core/parallel.hpp"

#include <algorithm>
#include <cmath>

namespace fsi::erp {

void ConvexFaces::resize(std::size_t n_points) {
  count.resize(n_points);
  for (std::size_t k = 0; k < max_planes; ++k) {
    n[k].resize(n_points);
    s[k].resize(n_points);
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

void TriangleLocator::convex_faces(std::span<const double> x, std::span<const double> y,
                                   std::span<const double> z, const TriangleHits& nearest,
                                   ConvexFaces& convex) const {
  const std::size_t n = x.size();
  convex.resize(n);
  if (!has_convex_edges_) { // no pair of triangles to take: no convex face anywhere
    std::fill(convex.count.begin(), convex.count.end(), 0);
    return;
  }
  const double tol = on_wall_tolerance * r_e_;
  parallel_for_balanced(n, [&](std::size_t i) {
    convex.count[i] = 0;
    const int t0 = nearest.triangle[i];
    if (t0 < 0) return;
    const Vec3 p(x[i], y[i], z[i]);
    const TriangleGeometry g0 = geometry(static_cast<std::size_t>(t0));
    std::array<Vec3, ConvexFaces::max_planes> normals;
    normals[0] = walls_->face_normal(t0);
    convex.n[0][i] = normals[0];
    convex.s[0][i] = (p - g0.a).dot(normals[0]);
    std::size_t count = 1;
    while (count < ConvexFaces::max_planes) {
      double best = r_e_ * r_e_;
      int best_id = -1;
      Vec3 best_a = Vec3::Zero();
      for_each_near(p, [&](const TriangleGeometry& g) {
        const Vec3& nt = walls_->face_normal(g.id);
        const bool turned =
            std::all_of(normals.begin() + 1, normals.begin() + count,
                        [&](const Vec3& m) { return m.dot(nt) < corner_face_max_cos; });
        if (!turned || !convex_pair(g0, normals[0], g, nt, tol)) return;
        const double d2 = (p - triangle_point(closest_on_triangle(p, g.a, g.b, g.c), g.a, g.b, g.c))
                              .squaredNorm();
        if (d2 < best || (d2 == best && best_id >= 0 && g.id < best_id))
          best = d2, best_id = g.id, best_a = g.a;
      });
      if (best_id < 0) break;
      normals[count] = walls_->face_normal(best_id);
      convex.n[count][i] = normals[count];
      convex.s[count][i] = (p - best_a).dot(normals[count]);
      ++count;
    }
    convex.count[i] = static_cast<unsigned char>(count - 1);
  });
}

} // namespace fsi::erp
