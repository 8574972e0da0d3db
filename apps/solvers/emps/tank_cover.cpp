#include "emps/tank_cover.hpp"

#include "fsi/core/error.hpp"
#include "fsi/core/format.hpp"

#include <Eigen/Geometry> // cross products

#include <cmath>
#include <string>
#include <utility>

namespace fsi::app::emps_plugin {

namespace {

using Polygon2 = std::vector<Vec2>;

double area(const Polygon2& p) { // the shoelace formula, counter-clockwise positive
  double twice = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec2& a = p[i];
    const Vec2& b = p[(i + 1) % p.size()];
    twice += a.x() * b.y() - a.y() * b.x();
  }
  return 0.5 * twice;
}

// The part of convex `p` on the left of the directed line a -> b (Sutherland-Hodgman, one edge).
Polygon2 clip(const Polygon2& p, const Vec2& a, const Vec2& b) {
  const auto side = [&](const Vec2& q) {
    const Vec2 e = b - a, r = q - a;
    return e.x() * r.y() - e.y() * r.x();
  };
  Polygon2 out;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec2 &u = p[i], &v = p[(i + 1) % p.size()];
    const double su = side(u), sv = side(v);
    if (su >= 0.0) out.push_back(u);
    if ((su < 0.0) != (sv < 0.0)) out.push_back(u + su / (su - sv) * (v - u));
  }
  return out;
}

// The area of the intersection of two triangles, each counter-clockwise in the plane.
double overlap(const Polygon2& face, const Polygon2& triangle) {
  Polygon2 p = face;
  for (std::size_t i = 0; i < 3 && !p.empty(); ++i) p = clip(p, triangle[i], triangle[(i + 1) % 3]);
  return p.size() < 3 ? 0.0 : area(p);
}

} // namespace

std::vector<std::array<int, 3>> uncovered_triangles(std::span<const Vec3> points,
                                                    std::span<const std::array<int, 3>> triangles,
                                                    const std::vector<InterfaceMesh3>& interfaces,
                                                    double tolerance) {
  std::vector<std::array<int, 3>> kept;
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const Vec3 &a = points[static_cast<std::size_t>(triangles[t][0])],
               &b = points[static_cast<std::size_t>(triangles[t][1])],
               &c = points[static_cast<std::size_t>(triangles[t][2])];
    // The triangle's plane: origin a, axes e1 along a -> b and e2 = n x e1 (counter-clockwise).
    const Vec3 n = (b - a).cross(c - a).normalized(), e1 = (b - a).normalized(), e2 = n.cross(e1);
    const auto in_plane = [&](const Vec3& x) { return Vec2((x - a).dot(e1), (x - a).dot(e2)); };
    const Polygon2 triangle = {in_plane(a), in_plane(b), in_plane(c)};
    const double whole = area(triangle);
    double covered = 0.0;
    std::size_t by = 0;
    for (std::size_t j = 0; j < interfaces.size(); ++j)
      for (const auto& face : interfaces[j].faces) {
        Polygon2 corners;
        for (std::size_t k = 0; k < 3; ++k) {
          const Vec3& x = interfaces[j].X0[face[k]];
          if (std::abs((x - a).dot(n)) <= tolerance) corners.push_back(in_plane(x));
        }
        if (corners.size() < 3) continue;
        if (area(corners) < 0.0) std::swap(corners[1], corners[2]); // a face seen from behind
        const double share = overlap(corners, triangle);
        if (share > 0.0) covered += share, by = j;
      }
    if (covered <= 1e-9 * whole) {
      kept.push_back(triangles[t]);
    } else if (covered < (1.0 - 1e-9) * whole) {
      throw InputError("tank triangle " + std::to_string(t + 1) + " is " +
                       significant(100.0 * covered / whole, 3) + " % covered by interface " +
                       std::to_string(by) +
                       " (a structure on the tank's wall must cover its triangles wholly or not "
                       "at all)");
    }
  }
  return kept;
}

} // namespace fsi::app::emps_plugin
