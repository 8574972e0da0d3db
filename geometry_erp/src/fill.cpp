#include "geometry_erp/fill.hpp"

#include "geometry_erp/grid_locator.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>

#include <cmath>

namespace fsi::erp {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_2;

std::vector<Point> to_cgal(const Polygon& polygon) {
  std::vector<Point> points;
  points.reserve(polygon.size());
  for (const Vec2& p : polygon) points.emplace_back(p.x(), p.y());
  return points;
}

CGAL::Bounded_side side(const std::vector<Point>& polygon, const Point& p) {
  return CGAL::bounded_side_2(polygon.begin(), polygon.end(), p, Kernel());
}

} // namespace

std::vector<Vec2> fill_lattice(const Vec2& origin, double l0, const std::vector<Polygon>& regions,
                               const std::vector<Polygon>& holes, const WallSet* walls) {
  std::vector<std::vector<Point>> region_points, hole_points;
  // Every boundary is a wall for the clearance test; copy the caller's segments after them.
  WallSet boundary;
  Vec2 lo = Vec2::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const Polygon& polygon : regions) {
    region_points.push_back(to_cgal(polygon));
    boundary.add_polyline(polygon, true, 0);
    for (const Vec2& p : polygon) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  }
  for (const Polygon& polygon : holes) {
    hole_points.push_back(to_cgal(polygon));
    boundary.add_polyline(polygon, true, 1);
  }
  if (walls != nullptr) {
    const int offset = static_cast<int>(boundary.nodes().size());
    for (const Vec2& x : walls->nodes().x) boundary.add_node(x);
    for (const auto& [a, b] : walls->segments().node)
      boundary.add_segment(a + offset, b + offset, 2);
  }
  std::vector<Vec2> particles;
  if (regions.empty()) return particles;

  // Candidate lattice points over the regions' bounding box.
  const auto i0 = static_cast<long>(std::floor((lo.x() - origin.x()) / l0)) - 1;
  const auto i1 = static_cast<long>(std::ceil((hi.x() - origin.x()) / l0)) + 1;
  const auto j0 = static_cast<long>(std::floor((lo.y() - origin.y()) / l0)) - 1;
  const auto j1 = static_cast<long>(std::ceil((hi.y() - origin.y()) / l0)) + 1;
  std::vector<Vec2> candidates;
  for (long j = j0; j <= j1; ++j)
    for (long i = i0; i <= i1; ++i) {
      const Vec2 p = origin + l0 * Vec2(static_cast<double>(i) + 0.5, static_cast<double>(j) + 0.5);
      const Point q(p.x(), p.y());
      bool inside = false;
      for (const auto& region : region_points)
        inside = inside || side(region, q) == CGAL::ON_BOUNDED_SIDE;
      for (const auto& hole : hole_points)
        inside = inside && side(hole, q) == CGAL::ON_UNBOUNDED_SIDE;
      if (inside) candidates.push_back(p);
    }

  // Clearance: nothing within l0/2 - tiny of a boundary or wall segment.
  const double clearance = 0.5 * l0 - 1e-9 * l0;
  const GridLocator locator(boundary, l0);
  WallHits hits;
  locator.query(candidates, hits);
  for (std::size_t k = 0; k < candidates.size(); ++k)
    if (hits.face[0].segment[k] < 0 || hits.face[0].r[k] >= clearance)
      particles.push_back(candidates[k]);
  return particles;
}

} // namespace fsi::erp
