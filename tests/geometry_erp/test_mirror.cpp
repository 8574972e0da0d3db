// Mirror helpers (eqs. 21-24).
#include "geometry_erp/mirror.hpp"
#include "geometry_erp/wall_locator.hpp"

#include <Eigen/LU>
#include <catch2/catch.hpp>

#include <random>

using namespace fsi;
using namespace fsi::erp;
using Catch::Matchers::WithinAbs;

TEST_CASE("erp: R_ref is an involution that flips n and keeps the tangent", "[mirror]") {
  for (const double angle : {0.0, 0.3, 1.7, -2.9}) {
    const Vec2 n(std::cos(angle), std::sin(angle)), tangent(-n.y(), n.x());
    const Mat2 R = R_ref(n);
    CHECK((R * R - Mat2::Identity()).norm() < 1e-15);
    CHECK_THAT(R.determinant(), WithinAbs(-1.0, 1e-15));
    CHECK((R * n + n).norm() < 1e-15);
    CHECK((R * tangent - tangent).norm() < 1e-15);
  }
  CHECK((R_inv() + Mat2::Identity()).norm() == 0.0);
}

TEST_CASE("erp: mirror of a point across a segment: other side, same distance", "[mirror]") {
  WallSet walls;
  const std::vector<Vec2> wall{{0.2, 0.1}, {1.3, 0.6}};
  walls.add_polyline(wall, false, 0);
  const Vec2 n_seg = walls.segment_normal(0);
  const auto locator = make_wall_locator(walls, 0.5);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec2> p;
  for (int k = 0; k < 200; ++k)
    p.push_back(Vec2(0.2, 0.1) + Vec2(1.1, 0.5) * (0.1 + 0.8 * u(rng)) + 0.4 * u(rng) * n_seg);
  WallHits hits;
  locator->query(p, hits);
  for (std::size_t i = 0; i < p.size(); ++i) {
    REQUIRE(hits.face[0].segment[i] == 0);
    const Vec2 x_mirror = mirror_position(p[i], hits.face[0].x_wall[i]);
    CHECK_THAT((x_mirror - hits.face[0].x_wall[i]).dot(n_seg),
               WithinAbs(-(p[i] - hits.face[0].x_wall[i]).dot(n_seg), 1e-14));
    CHECK_THAT((x_mirror - hits.face[0].x_wall[i]).norm(), WithinAbs(hits.face[0].r[i], 1e-14));
    // The reflection about the wall line maps the particle onto its mirror (eq. 21 and 23).
    CHECK((hits.face[0].x_wall[i] +
           R_ref(hits.face[0].n_wall[i]) * (p[i] - hits.face[0].x_wall[i]) - x_mirror)
              .norm() < 1e-14);
  }
}

TEST_CASE("erp: mirrored velocities: no-slip averages to the wall's tangential velocity",
          "[mirror]") {
  const Vec2 n = Vec2(0.6, 0.8), tangent(-0.8, 0.6);
  const Vec2 v_wall(0.3, -1.2), v_i(2.0, 0.7);
  const Vec2 no_slip = mirror_velocity_no_slip(v_i, v_wall, n);
  const Vec2 mean = 0.5 * (v_i + no_slip);
  CHECK((mean - v_wall.dot(tangent) * tangent).norm() < 1e-15);
  // Slip: normal part of the mean is the wall's, tangential part is the particle's.
  const Vec2 slip = mirror_velocity_slip(v_i, v_wall, n);
  const Vec2 slip_mean = 0.5 * (v_i + slip);
  CHECK_THAT(slip_mean.dot(n), WithinAbs(v_wall.dot(n), 1e-15));
  CHECK_THAT(slip_mean.dot(tangent), WithinAbs(v_i.dot(tangent), 1e-15));
}
