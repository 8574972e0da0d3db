// The corner faces of TriangleLocator: the other planes of a concave edge or corner.
#include "geometry_erp/triangle_locator.hpp"
#include "geometry_erp/wall_locator.hpp"

#include "fsi/core/parallel.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fsi::erp {

void TriangleLocator::corner_faces(std::span<const double> x, std::span<const double> y,
                                   std::span<const double> z, std::span<TriangleHits> faces) const {
  const std::size_t n = x.size();
  for (std::size_t k = 1; k < faces.size(); ++k) faces[k].resize(n);
  parallel_for_balanced(n, [&](std::size_t i) {
    const Vec3 p(x[i], y[i], z[i]);
    std::array<Vec3, 3> normals;
    std::size_t count = 0;
    for (std::size_t k = 1; k < faces.size(); ++k) faces[k].triangle[i] = -1;
    if (faces[0].triangle[i] < 0) return;
    normals[count++] = faces[0].n_wall[i];
    for (std::size_t k = 1; k < faces.size() && count < normals.size(); ++k) {
      corner_face(p, std::span<const Vec3>(normals.data(), count), faces[k], i);
      if (faces[k].triangle[i] < 0) return;
      normals[count++] = faces[k].n_wall[i];
    }
  });
}

void TriangleLocator::corner_face(const Vec3& p, std::span<const Vec3> normals, TriangleHits& face,
                                  std::size_t i) const {
  face.triangle[i] = -1;
  const double min_r = on_wall_tolerance * r_e_;
  double best = r_e_;
  int best_id = -1;
  Vec3 best_bary = Vec3::Zero();
  for_each_near(p, [&](const TriangleGeometry& g) {
    const Vec3& nt = walls_->face_normal(g.id);
    const double d = (p - g.a).dot(nt);
    if (d <= min_r || d > best || (d == best && g.id > best_id)) return;
    const bool turned = std::all_of(normals.begin(), normals.end(),
                                    [&](const Vec3& m) { return m.dot(nt) < corner_face_max_cos; });
    if (!turned) return;
    // Barycentric coordinates of the foot p - d n_t (edges included, to round-off).
    const Vec3 foot = p - d * nt, ab = g.b - g.a, ac = g.c - g.a, af = foot - g.a;
    const double area2 = ab.cross(ac).dot(nt);
    const double v = af.cross(ac).dot(nt) / area2, w = ab.cross(af).dot(nt) / area2;
    const double tol = -1e-12;
    if (v < tol || w < tol || 1.0 - v - w < tol) return;
    best = d, best_id = g.id, best_bary = Vec3(1.0 - v - w, v, w);
  });
  if (best_id < 0) return;
  const auto& abc = walls_->triangles().node[static_cast<std::size_t>(best_id)];
  const auto& nodes = walls_->nodes();
  const auto ua = static_cast<std::size_t>(abc[0]), ub = static_cast<std::size_t>(abc[1]),
             uc = static_cast<std::size_t>(abc[2]);
  const Vec3& nt = walls_->face_normal(best_id);
  face.triangle[i] = best_id;
  face.feature[i] = TriangleFeature::face;
  face.bary[i] = best_bary;
  face.r[i] = best;
  face.x_wall[i] = p - best * nt;
  face.n_wall[i] = nt;
  face.v_wall[i] =
      best_bary[0] * nodes.v[ua] + best_bary[1] * nodes.v[ub] + best_bary[2] * nodes.v[uc];
  face.a_wall[i] =
      best_bary[0] * nodes.a[ua] + best_bary[1] * nodes.a[ub] + best_bary[2] * nodes.a[uc];
  face.crossed[i] = 0;
}

} // namespace fsi::erp
