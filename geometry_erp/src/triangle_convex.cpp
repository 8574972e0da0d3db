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
} // namespace

void TriangleLocator::convex_faces(std::span<const double> x, std::span<const double> y,
                                   std::span<const double> z, const TriangleHits& nearest,
                                   ConvexFaces& convex) const {
  const std::size_t n = x.size();
  convex.resize(n);
  const double tol = on_wall_tolerance * r_e_;
  parallel_for_balanced(n, [&](std::size_t i) {
    convex.count[i] = 0;
    const int t0 = nearest.triangle[i];
    if (t0 < 0) return;
    const Vec3 p(x[i], y[i], z[i]);
    const auto& abc = walls_->triangles().node[static_cast<std::size_t>(t0)];
    const auto& nodes = walls_->nodes().x;
    const TriangleGeometry g0{nodes[static_cast<std::size_t>(abc[0])],
                              nodes[static_cast<std::size_t>(abc[1])],
                              nodes[static_cast<std::size_t>(abc[2])], t0};
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
            std::all_of(normals.begin(), normals.begin() + count,
                        [&](const Vec3& m) { return m.dot(nt) < corner_face_max_cos; });
        if (!turned || !behind_plane(g, g0.a, normals[0], tol) || !behind_plane(g0, g.a, nt, tol))
          return;
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
