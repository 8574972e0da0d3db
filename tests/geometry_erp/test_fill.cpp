// Initial lattice filling inside regions, minus holes, clear of walls.
#include "geometry_erp/fill.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

using namespace fsi;
using namespace fsi::erp;

namespace {

double distance_to_segment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const double t = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
  return (p - (a + t * (b - a))).norm();
}

double min_distance(const std::vector<Vec2>& particles, const Polygon& polygon) {
  double d = std::numeric_limits<double>::infinity();
  for (const Vec2& p : particles)
    for (std::size_t k = 0; k < polygon.size(); ++k)
      d = std::min(d, distance_to_segment(p, polygon[k], polygon[(k + 1) % polygon.size()]));
  return d;
}

Polygon rectangle(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

} // namespace

TEST_CASE("erp: fill: a rectangle gets the analytic lattice count", "[fill]") {
  const double l0 = 1.46e-3;
  // The dam-break water column 0.146 x 0.292 m: 100 x 200 particles.
  const auto water = fill_lattice(Vec2(0, 0), l0, {rectangle(0.0, 0.0, 100 * l0, 200 * l0)});
  CHECK(water.size() == 20000);
  CHECK(min_distance(water, rectangle(0.0, 0.0, 100 * l0, 200 * l0)) >= 0.5 * l0 - 1e-9 * l0);
  // Width not a multiple of l0: columns i with (i + 1/2) l0 <= W - l0/2, i.e. floor(W/l0) of them.
  const double W = 37.6 * l0, H = 12.2 * l0;
  const auto block = fill_lattice(Vec2(0, 0), l0, {rectangle(0.0, 0.0, W, H)});
  CHECK(block.size() == 37u * 12u);
  // Clockwise input works the same.
  const auto clockwise = fill_lattice(Vec2(0, 0), l0, {{{0.0, 0.0}, {0.0, H}, {W, H}, {W, 0.0}}});
  CHECK(clockwise.size() == block.size());
}

TEST_CASE("erp: fill: holes and walls are excluded with l0/2 clearance", "[fill]") {
  const double l0 = 0.01;
  const Polygon tank = rectangle(0.0, 0.0, 1.0, 0.6);
  Polygon hole;
  const Vec2 centre(0.5, 0.3);
  const double R = 0.1;
  for (int k = 0; k < 64; ++k) {
    const double a = 2.0 * std::numbers::pi * k / 64;
    hole.push_back(centre + R * Vec2(std::cos(a), std::sin(a)));
  }
  WallSet walls;
  walls.add_polyline(std::vector<Vec2>{{0.2, 0.1}, {0.2, 0.5}}, false, 0); // a thin plate
  const auto particles = fill_lattice(Vec2(0, 0), l0, {tank}, {hole}, &walls);
  CHECK(min_distance(particles, tank) >= 0.5 * l0 - 1e-9 * l0);
  CHECK(min_distance(particles, hole) >= 0.5 * l0 - 1e-9 * l0);
  double d_plate = std::numeric_limits<double>::infinity();
  for (const Vec2& p : particles) {
    REQUIRE((p - centre).norm() > R * std::cos(std::numbers::pi / 64));
    d_plate = std::min(d_plate, distance_to_segment(p, {0.2, 0.1}, {0.2, 0.5}));
  }
  CHECK(d_plate >= 0.5 * l0 - 1e-9 * l0);
  // The plate sits on lattice lines x = 0.2 (between columns): the columns at 0.195 and 0.205 are
  // exactly l0/2 away and stay, so only the hole removes particles: about pi R^2 / l0^2 of them.
  const double removed = 100.0 * 60.0 - static_cast<double>(particles.size());
  CHECK_THAT(removed, Catch::Matchers::WithinAbs(std::numbers::pi * R * R / (l0 * l0), 30.0));
}
