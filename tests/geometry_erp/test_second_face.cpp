// Second face of concave corners (wall_locator.hpp): both back-ends against a brute force written
// independently, and the faces of a rectangular tank's corner.
#include "geometry_erp/wall_locator.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <random>

using namespace fsi;
using namespace fsi::erp;
using Catch::Matchers::WithinAbs;

namespace {

struct Face {
  int segment = -1;
  double r = std::numeric_limits<double>::infinity();
};

/// Nearest segment other than `first`, within r_e, with its foot strictly inside, the point on
/// its left, and a normal more than 30 degrees away from n1.
Face brute_second_face(const WallSet& walls, const Vec2& p, int first, const Vec2& n1, double r_e) {
  Face best;
  for (std::size_t s = 0; s < walls.segments().size(); ++s) {
    if (static_cast<int>(s) == first) continue;
    const Vec2 a = walls.nodes().x[static_cast<std::size_t>(walls.segments().node[s][0])];
    const Vec2 b = walls.nodes().x[static_cast<std::size_t>(walls.segments().node[s][1])];
    const double len = (b - a).norm();
    const Vec2 e = (b - a) / len;
    const double along = (p - a).dot(e);
    if (along <= 0.0 || along >= len) continue;
    const Vec2 d = p - (a + along * e);
    const double r = d.norm();
    const Vec2 left(-e.y(), e.x());
    if (r >= r_e || d.dot(left) <= 0.0) continue;
    if (d.dot(n1) / r > std::cos(std::numbers::pi / 6.0)) continue;
    if (r < best.r) best = {static_cast<int>(s), r};
  }
  return best;
}

} // namespace

TEST_CASE("erp: second face: both back-ends agree with brute force", "[nearest]") {
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int with_face = 0, without = 0;
  for (int polygon = 0; polygon < 400; ++polygon) {
    std::vector<Vec2> points;
    const int n = 4 + polygon % 9;
    for (int k = 0; k < n; ++k) {
      const double a = 2.0 * std::numbers::pi * (k + 0.8 * u(rng)) / n;
      points.push_back((0.3 + 0.7 * u(rng)) * Vec2(std::cos(a), std::sin(a)));
    }
    WallSet walls;
    walls.add_polyline(points, true, 0);
    const double r_e = 0.1 + 0.3 * u(rng);
    std::vector<Vec2> particles;
    for (int k = 0; k < 200; ++k) particles.push_back(Vec2(2.4 * u(rng) - 1.2, 2.4 * u(rng) - 1.2));
    for (const LocatorKind kind : {LocatorKind::grid, LocatorKind::aabb_tree}) {
      auto locator = make_wall_locator(walls, r_e, kind);
      locator->set_corner_faces(true);
      WallHits hits;
      locator->query(particles, hits);
      for (std::size_t i = 0; i < particles.size(); ++i) {
        if (hits.face[0].segment[i] < 0) {
          REQUIRE(hits.face[1].segment[i] == -1);
          continue;
        }
        const Face face = brute_second_face(walls, particles[i], hits.face[0].segment[i],
                                            hits.face[0].n_wall[i], r_e);
        REQUIRE(hits.face[1].segment[i] == face.segment);
        if (face.segment < 0) {
          ++without;
          continue;
        }
        ++with_face;
        REQUIRE_THAT(hits.face[1].r[i], WithinAbs(face.r, 1e-12));
        REQUIRE_THAT((particles[i] - hits.face[1].x_wall[i]).norm(), WithinAbs(face.r, 1e-12));
        REQUIRE((hits.face[1].n_wall[i] - (particles[i] - hits.face[1].x_wall[i]) / face.r).norm() <
                1e-12);
      }
    }
  }
  CHECK(with_face > 1000);
  CHECK(without > 1000);
}

TEST_CASE("erp: second face: a rectangular tank's corner has two faces, a straight wall one",
          "[nearest]") {
  WallSet walls;
  // Counter-clockwise tank, the bottom split into two segments (a straight wall of two pieces).
  const std::vector<Vec2> tank{{0, 1}, {0, 0}, {0.5, 0}, {1, 0}, {1, 1}};
  walls.add_polyline(tank, false, 0);
  for (const LocatorKind kind : {LocatorKind::grid, LocatorKind::aabb_tree}) {
    auto locator = make_wall_locator(walls, 0.3, kind);
    WallHits hits;
    const std::vector<Vec2> p{{0.1, 0.05}, {0.5, 0.05}, {0.45, 0.1}, {0.95, 0.5}};
    locator->query(p, hits);
    CHECK(hits.face[1].segment[0] == -1); // not asked for
    locator->set_corner_faces(true);
    locator->query(p, hits);
    // Near the bottom-left corner: the floor first, the left wall second.
    CHECK(hits.face[0].segment[0] == 1);
    CHECK(hits.face[1].segment[0] == 0);
    CHECK_THAT(hits.face[1].r[0], WithinAbs(0.1, 1e-15));
    CHECK((hits.face[1].n_wall[0] - Vec2(1, 0)).norm() < 1e-15);
    // Over the joint of the two floor segments, and beside it: one face only.
    CHECK(hits.face[1].segment[1] == -1);
    CHECK(hits.face[1].segment[2] == -1);
    // Beside the right wall, far from the floor: one face.
    CHECK(hits.face[1].segment[3] == -1);
  }
}

TEST_CASE("erp: nearest wall: a particle beyond the free end of an open wall is not crossed",
          "[nearest]") {
  // An open U tank (fluid inside); a particle that splashed over the top of the left wall and
  // came down just outside it is beyond the wall's free end, not inside a solid.
  WallSet walls;
  const std::vector<Vec2> tank{{0, 0.8}, {0, 0}, {1, 0}, {1, 0.8}};
  walls.add_polyline(tank, false, 0);
  for (const LocatorKind kind : {LocatorKind::grid, LocatorKind::aabb_tree}) {
    auto locator = make_wall_locator(walls, 0.05, kind);
    WallHits hits;
    const std::vector<Vec2> p{{-3e-6, 0.824}, {-0.01, 0.7}, {0.01, 0.81}};
    locator->query(p, hits);
    CHECK(hits.face[0].segment[0] == 0);
    CHECK((hits.face[0].x_wall[0] - Vec2(0, 0.8)).norm() < 1e-15);
    CHECK(hits.crossed[0] == 0); // above the free end
    CHECK(hits.crossed[1] == 1); // beside the wall, on its solid side
    CHECK(hits.crossed[2] == 0); // inside, above the end
  }
}
