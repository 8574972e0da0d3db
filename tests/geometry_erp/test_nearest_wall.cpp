// Nearest wall point (eqs. 18-19) of both back-ends against brute force over random star-shaped
// polygons, with points on vertices, on segments, near and behind walls; crossing flags against
// CGAL's inside/outside test.
#include "fsi/core/parallel.hpp"
#include "geometry_erp/aabb_locator.hpp"
#include "geometry_erp/grid_locator.hpp"
#include "geometry_erp/wall_locator.hpp"

#include <catch2/catch.hpp>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

using namespace fsi;
using namespace fsi::erp;
using Catch::Matchers::WithinAbs;

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

/// A random polygon, star-shaped around `center` (hence simple) and counter-clockwise: vertex
/// angles jittered within equal sectors, so consecutive angles are less than pi apart.
std::vector<Vec2> star_polygon(std::mt19937& rng, const Vec2& center, double radius) {
  std::uniform_int_distribution<int> count(4, 14);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int n = count(rng);
  std::vector<Vec2> points;
  for (int k = 0; k < n; ++k) {
    const double a = 2.0 * std::numbers::pi * (k + 0.8 * u(rng)) / n;
    const double r = radius * (0.3 + 0.7 * u(rng));
    points.push_back(center + r * Vec2(std::cos(a), std::sin(a)));
  }
  return points;
}

struct Brute {
  int segment = -1;
  double t = 0.0, r = std::numeric_limits<double>::infinity();
  Vec2 x_wall;
};

/// Nearest point by looping over all segments (written independently of the library).
Brute brute_force(const WallSet& walls, const Vec2& p) {
  Brute best;
  const auto& x = walls.nodes().x;
  for (std::size_t s = 0; s < walls.segments().size(); ++s) {
    const Vec2 a = x[static_cast<std::size_t>(walls.segments().node[s][0])];
    const Vec2 b = x[static_cast<std::size_t>(walls.segments().node[s][1])];
    const double len = (b - a).norm();
    const Vec2 e = (b - a) / len;
    const double along = std::min(std::max((p - a).dot(e), 0.0), len);
    const Vec2 q = a + along * e;
    const double r = (p - q).norm();
    if (r < best.r) best = {static_cast<int>(s), along / len, r, q};
  }
  return best;
}

Vec2 left_normal(const Vec2& a, const Vec2& b) {
  return Vec2(a.y() - b.y(), b.x() - a.x()).normalized();
}

} // namespace

TEST_CASE("erp: nearest wall: both back-ends agree with brute force on random polygons",
          "[nearest]") {
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int checked = 0, crossed_checked = 0, on_vertex = 0, on_segment = 0;
  for (int polygon = 0; polygon < 5000; ++polygon) {
    const double radius = 0.5 + u(rng);
    const Vec2 center(4.0 * u(rng) - 2.0, 4.0 * u(rng) - 2.0);
    std::vector<Vec2> points = star_polygon(rng, center, radius);
    const bool fluid_inside = polygon % 2 == 0;
    if (!fluid_inside) std::reverse(points.begin(), points.end()); // clockwise: fluid outside
    WallSet walls;
    walls.add_polyline(points, true, 7);
    for (std::size_t L = 0; L < walls.nodes().size(); ++L) {
      walls.nodes().v[L] = Vec2(u(rng), u(rng));
      walls.nodes().a[L] = Vec2(u(rng), u(rng));
    }
    const double r_e = radius * (0.1 + 0.4 * u(rng));

    // Random points around the polygon, its vertices, and points on its segments.
    std::vector<Vec2> particles;
    for (int k = 0; k < 24; ++k)
      particles.push_back(center + (radius + r_e) * Vec2(2.0 * u(rng) - 1.0, 2.0 * u(rng) - 1.0));
    const std::size_t first_vertex = particles.size();
    particles.insert(particles.end(), points.begin(), points.end());
    const std::size_t first_on_segment = particles.size();
    for (std::size_t k = 0; k < points.size(); ++k) {
      const double t = 0.05 + 0.9 * u(rng);
      particles.push_back((1.0 - t) * points[k] + t * points[(k + 1) % points.size()]);
    }

    std::vector<Kernel::Point_2> cgal_polygon;
    for (const Vec2& p : points) cgal_polygon.emplace_back(p.x(), p.y());

    for (const LocatorKind kind : {LocatorKind::grid, LocatorKind::aabb_tree}) {
      const auto locator = make_wall_locator(walls, r_e, kind);
      WallHits hits;
      locator->query(particles, hits);
      for (std::size_t i = 0; i < particles.size(); ++i) {
        const Vec2& p = particles[i];
        const Brute brute = brute_force(walls, p);
        if (brute.r >= r_e * (1.0 - 1e-12)) {
          if (brute.r > r_e * (1.0 + 1e-12)) REQUIRE(hits.face[0].segment[i] == -1);
          continue;
        }
        REQUIRE(hits.face[0].segment[i] >= 0);
        ++checked;
        REQUIRE_THAT(hits.face[0].r[i], WithinAbs(brute.r, 1e-12));
        REQUIRE((hits.face[0].x_wall[i] - brute.x_wall).norm() < 1e-12);
        REQUIRE_THAT(hits.face[0].n_wall[i].norm(), WithinAbs(1.0, 1e-12));
        // Wall velocity and acceleration: linear along the segment that was found.
        const auto [a, b] =
            walls.segments().node[static_cast<std::size_t>(hits.face[0].segment[i])];
        const double t = hits.face[0].t[i];
        const auto& v = walls.nodes().v;
        REQUIRE((hits.face[0].v_wall[i] -
                 ((1.0 - t) * v[static_cast<std::size_t>(a)] + t * v[static_cast<std::size_t>(b)]))
                    .norm() < 1e-14);
        REQUIRE(
            (hits.face[0].x_wall[i] - ((1.0 - t) * walls.nodes().x[static_cast<std::size_t>(a)] +
                                       t * walls.nodes().x[static_cast<std::size_t>(b)]))
                .norm() < 1e-12);

        if (i >= first_vertex && i < first_on_segment) {
          // Exactly on a vertex: distance 0, the angle-weighted pseudo-normal, not crossed.
          const std::size_t k = i - first_vertex, n = points.size();
          const Vec2 pseudo = (left_normal(points[(k + n - 1) % n], points[k]) +
                               left_normal(points[k], points[(k + 1) % n]))
                                  .normalized();
          REQUIRE(hits.face[0].r[i] == 0.0);
          REQUIRE((hits.face[0].n_wall[i] - pseudo).norm() < 1e-12);
          REQUIRE(hits.crossed[i] == 0);
          ++on_vertex;
        } else if (i >= first_on_segment) {
          // On a segment: the segment's fluid normal, not crossed.
          const std::size_t k = i - first_on_segment;
          REQUIRE(hits.face[0].r[i] < 1e-12);
          REQUIRE((hits.face[0].n_wall[i] - left_normal(points[k], points[(k + 1) % points.size()]))
                      .norm() < 1e-12);
          REQUIRE(hits.crossed[i] == 0);
          ++on_segment;
        } else {
          REQUIRE(
              (hits.face[0].n_wall[i] - (p - hits.face[0].x_wall[i]) / hits.face[0].r[i]).norm() <
              1e-12); // eq. 19
          const auto side = CGAL::bounded_side_2(cgal_polygon.begin(), cgal_polygon.end(),
                                                 Kernel::Point_2(p.x(), p.y()), Kernel());
          REQUIRE(side != CGAL::ON_BOUNDARY);
          const bool in_solid = (side == CGAL::ON_BOUNDED_SIDE) != fluid_inside;
          REQUIRE(static_cast<bool>(hits.crossed[i]) == in_solid);
          ++crossed_checked;
        }
      }
    }
  }
  CHECK(checked > 100000);
  CHECK(crossed_checked > 50000);
  CHECK(on_vertex > 40000);
  CHECK(on_segment > 40000);
}

TEST_CASE("erp: nearest wall: convex and concave corners of a tank", "[nearest]") {
  // Counter-clockwise L-shaped tank: fluid inside; the corner (1, 1) is concave seen from the
  // fluid.
  WallSet walls;
  const std::vector<Vec2> tank{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  walls.add_polyline(tank, true, 0);
  for (const LocatorKind kind : {LocatorKind::grid, LocatorKind::aabb_tree}) {
    const auto locator = make_wall_locator(walls, 0.3, kind);
    WallHits hits;
    const std::vector<Vec2> p{{0.1, 0.05}, {-0.1, -0.1}, {0.9, 0.9}, {1.1, 1.2}, {1.1, 1.1}};
    locator->query(p, hits);
    // Near the bottom wall.
    CHECK(hits.face[0].segment[0] == 0);
    CHECK_THAT(hits.face[0].r[0], WithinAbs(0.05, 1e-15));
    CHECK((hits.face[0].n_wall[0] - Vec2(0, 1)).norm() < 1e-15);
    CHECK(hits.crossed[0] == 0);
    // Outside the convex corner (0, 0): nearest is the vertex, crossed.
    CHECK((hits.face[0].x_wall[1] - Vec2(0, 0)).norm() < 1e-15);
    CHECK(hits.crossed[1] == 1);
    // Inside near the concave corner: nearest is the corner, pointing into the fluid.
    CHECK((hits.face[0].x_wall[2] - Vec2(1, 1)).norm() < 1e-15);
    CHECK_THAT(hits.face[0].r[2], WithinAbs(0.1 * std::sqrt(2.0), 1e-15));
    CHECK(hits.crossed[2] == 0);
    // Behind the concave corner, in the solid: crossed whichever wall is nearest.
    CHECK(hits.crossed[3] == 1);
    CHECK_THAT(hits.face[0].r[3], WithinAbs(0.1, 1e-15));
    CHECK(hits.crossed[4] == 1);
  }
}

TEST_CASE("erp: nearest wall: SoA overload, thread count and refit give the same answer",
          "[nearest]") {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  WallSet walls;
  for (int k = 0; k < 20; ++k)
    walls.add_polyline(star_polygon(rng, Vec2(10.0 * u(rng), 10.0 * u(rng)), 1.0), true, k);
  std::vector<Vec2> p(20000);
  std::vector<double> px(p.size()), py(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    p[i] = Vec2(10.0 * u(rng), 10.0 * u(rng));
    px[i] = p[i].x();
    py[i] = p[i].y();
  }
  for (const LocatorKind kind : {LocatorKind::grid, LocatorKind::aabb_tree}) {
    auto locator = make_wall_locator(walls, 0.4, kind);
    WallHits parallel, sequential, soa;
    locator->query(p, parallel);
    set_sequential(true);
    locator->query(p, sequential);
    set_sequential(false);
    locator->query(px, py, soa);
    int hits = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      REQUIRE(parallel.face[0].segment[i] == sequential.face[0].segment[i]);
      REQUIRE(parallel.face[0].segment[i] == soa.face[0].segment[i]);
      REQUIRE(parallel.face[0].r[i] == soa.face[0].r[i]);
      hits += parallel.face[0].segment[i] >= 0;
    }
    CHECK(hits > 1000);

    // Move every node, update, compare with brute force.
    WallSet moved = walls;
    for (Vec2& x : moved.nodes().x) x += Vec2(0.3, -0.2) + 0.05 * Vec2(u(rng), u(rng));
    auto moved_locator = make_wall_locator(moved, 0.4, kind);
    for (Vec2& x : moved.nodes().x) x += Vec2(-0.1, 0.25);
    moved_locator->update();
    WallHits after;
    moved_locator->query(p, after);
    for (std::size_t i = 0; i < p.size(); i += 7) {
      const Brute brute = brute_force(moved, p[i]);
      if (brute.r < 0.4 * (1.0 - 1e-12))
        REQUIRE_THAT(after.face[0].r[i], WithinAbs(brute.r, 1e-12));
      if (brute.r > 0.4 * (1.0 + 1e-12)) REQUIRE(after.face[0].segment[i] == -1);
    }
  }
}

TEST_CASE("erp: nearest wall: an empty wall set or a far particle gives no hit", "[nearest]") {
  WallSet empty;
  WallSet one;
  one.add_polyline(std::vector<Vec2>{{0.0, 0.0}, {1.0, 0.0}}, false, 0);
  const std::vector<Vec2> p{{0.5, 0.2}, {0.5, 5.0}, {-1e300, 1e300}};
  for (const LocatorKind kind : {LocatorKind::grid, LocatorKind::aabb_tree}) {
    WallHits hits;
    make_wall_locator(empty, 0.3, kind)->query(p, hits);
    for (std::size_t i = 0; i < p.size(); ++i) CHECK(hits.face[0].segment[i] == -1);
    make_wall_locator(one, 0.3, kind)->query(p, hits);
    CHECK(hits.face[0].segment[0] == 0);
    CHECK_THAT(hits.face[0].r[0], WithinAbs(0.2, 1e-15));
    CHECK(hits.face[0].segment[1] == -1);
    CHECK(std::isinf(hits.face[0].r[1]));
    CHECK(hits.face[0].segment[2] == -1);
  }
}
