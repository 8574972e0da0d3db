// Seeding: the lattice fill of a polygon (2-D) or a box (3-D).
#include "solid_tlsph/geometry.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "fsi/core/error.hpp"
#include "particles/lattice.hpp"

namespace fsi::tlsph {

namespace {

void require_positive_spacing(double dp) {
  if (!(dp > 0.0)) {
    std::ostringstream s;
    s << "tlsph geometry: dp = " << dp << " must be > 0";
    throw InputError(s.str());
  }
}

} // namespace

bool inside_polygon(const std::vector<Vec2>& polygon, const Vec2& X) {
  bool in = false;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Vec2 &a = polygon[i], &b = polygon[j];
    if ((a.y() > X.y()) != (b.y() > X.y()) &&
        X.x() < (b.x() - a.x()) * (X.y() - a.y()) / (b.y() - a.y()) + a.x())
      in = !in;
  }
  return in;
}

SolidGeometry fill_polygon(const std::vector<Vec2>& polygon, std::vector<std::string> tags,
                           double dp, const Vec2& origin) {
  require_positive_spacing(dp);
  const std::size_t n = polygon.size();
  if (n < 3)
    throw InputError("tlsph geometry: a polygon needs at least 3 vertices, got " +
                     std::to_string(n));
  double area2 = 0.0; // twice the signed area (> 0: counter-clockwise)
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 &a = polygon[i], &b = polygon[(i + 1) % n];
    area2 += a.x() * b.y() - b.x() * a.y();
  }
  if (!(area2 > 0.0))
    throw InputError("tlsph geometry: the polygon must be counter-clockwise (solid on the left)");
  if (tags.empty()) tags.assign(n, "boundary");
  if (tags.size() != n)
    throw InputError("tlsph geometry: " + std::to_string(tags.size()) + " edge tags for " +
                     std::to_string(n) + " edges");
  Vec2 lo = polygon.front(), hi = polygon.front();
  for (const Vec2& p : polygon) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const long i0 = static_cast<long>(std::floor((lo.x() - origin.x()) / dp)) - 1;
  const long i1 = static_cast<long>(std::ceil((hi.x() - origin.x()) / dp)) + 1;
  const long j0 = static_cast<long>(std::floor((lo.y() - origin.y()) / dp)) - 1;
  const long j1 = static_cast<long>(std::ceil((hi.y() - origin.y()) / dp)) + 1;
  SolidGeometry g;
  for (long j = j0; j <= j1; ++j)
    for (long i = i0; i <= i1; ++i) {
      const Vec2 X = origin + dp * Vec2(static_cast<double>(i) + 0.5, static_cast<double>(j) + 0.5);
      if (inside_polygon(polygon, X)) g.X0.push_back(X), g.V0.push_back(dp * dp);
    }
  g.outline = polygon;
  g.outline_tags = std::move(tags);
  return g;
}

SolidGeometry fill_rectangle(const Vec2& lo, const Vec2& hi, double dp) {
  if (!(hi.x() > lo.x() && hi.y() > lo.y()))
    throw InputError("tlsph geometry: rectangle needs hi > lo in x and y");
  return fill_polygon({lo, {hi.x(), lo.y()}, hi, {lo.x(), hi.y()}},
                      {"bottom", "right", "top", "left"}, dp, lo);
}

SolidGeometry3 fill_box(const Vec3& lo, const Vec3& hi, double dp) {
  require_positive_spacing(dp);
  if (!(hi.x() > lo.x() && hi.y() > lo.y() && hi.z() > lo.z()))
    throw InputError("tlsph geometry: box needs hi > lo in x, y and z");
  // Points at dp/2 from the sides; a side that is not a multiple of dp keeps the whole layers.
  SolidGeometry3 g;
  g.X0 = particles::lattice_box<3>(lo, hi, dp);
  g.V0.assign(g.X0.size(), dp * dp * dp);
  g.box = {lo, hi};
  return g;
}

} // namespace fsi::tlsph
