// Prescribed rigid motion: node velocity and acceleration against finite differences of node
// positions (second order: the error drops by 4 when h halves), CSV tables and their errors.
#include "fsi/core/error.hpp"
#include "geometry_erp/motion.hpp"
#include "geometry_erp/wall_set.hpp"

#include <catch2/catch.hpp>

#include <numbers>
#include <string>

using namespace fsi;
using namespace fsi::erp;

namespace {

struct FdErrors {
  double v, a;
};

/// Central-difference errors of the node velocity and acceleration at time t with step h.
FdErrors fd_errors(const Motion& motion, const Vec2& pivot, const Vec2& X, double t, double h) {
  const auto x = [&](double s) { return rigid_node_state(motion.at(s), pivot, X).x; };
  const NodeState exact = rigid_node_state(motion.at(t), pivot, X);
  const Vec2 v_fd = (x(t + h) - x(t - h)) / (2.0 * h);
  const Vec2 a_fd = (x(t + h) - 2.0 * x(t) + x(t - h)) / (h * h);
  return {(v_fd - exact.v).norm(), (a_fd - exact.a).norm()};
}

void check_second_order(const Motion& motion, double t, double h) {
  const Vec2 pivot(0.3, -0.2), X(1.1, 0.7);
  const FdErrors coarse = fd_errors(motion, pivot, X, t, h);
  const FdErrors fine = fd_errors(motion, pivot, X, t, 0.5 * h);
  CHECK(coarse.v > 1e-9);
  CHECK(coarse.a > 1e-9);
  CHECK_THAT(coarse.v / fine.v, Catch::Matchers::WithinAbs(4.0, 0.05));
  CHECK_THAT(coarse.a / fine.a, Catch::Matchers::WithinAbs(4.0, 0.05));
}

std::string data(const char* name) {
  return std::string(FSI_TEST_DATA) + "/" + name;
}

} // namespace

TEST_CASE("erp: sinusoidal translation plus rotation: v and a are the derivatives of x",
          "[motion]") {
  const SumMotion motion(
      {std::make_shared<SinusoidTranslation>(Vec2(0.05, -0.02), 0.9, 0.4),
       std::make_shared<SinusoidRotation>(4.0 * std::numbers::pi / 180.0, 1.211, 0.1)});
  for (const double t : {0.0, 0.37, 1.9}) check_second_order(motion, t, 1e-2);
}

TEST_CASE("erp: sinusoid: value at a quarter period is the amplitude", "[motion]") {
  const SinusoidRotation rotation(0.07, 2.0, 0.0);
  CHECK_THAT(rotation.at(0.5).theta, Catch::Matchers::WithinAbs(0.07, 1e-15));
  CHECK_THAT(rotation.at(0.5).omega, Catch::Matchers::WithinAbs(0.0, 1e-15));
  const SinusoidTranslation translation(Vec2(0.1, 0.2), 2.0, 0.0);
  CHECK_THAT(translation.at(0.5).d_ddot.y(),
             Catch::Matchers::WithinRel(-0.2 * std::numbers::pi * std::numbers::pi, 1e-14));
}

TEST_CASE("erp: CSV tables: spline through the rows, v and a second-order consistent", "[motion]") {
  const auto rotation = std::make_shared<TableRotation>(data("motion_rotation.csv"));
  const auto translation = std::make_shared<TableTranslation>(data("motion_translation.csv"));
  // Row t = 0.5 of the rotation table.
  const double theta_row = 0.3 * std::sin(2.0 * std::numbers::pi * 0.5 / 1.2) + 0.05 * 0.25;
  CHECK_THAT(rotation->at(0.5).theta, Catch::Matchers::WithinAbs(theta_row, 1e-15));
  const SumMotion motion({rotation, translation});
  // Midpoints of table intervals, h small enough to stay inside one cubic piece.
  for (const double t : {0.725, 1.275}) check_second_order(motion, t, 0.01);
  // Spline close to the sampled function between rows.
  const double t = 0.725;
  CHECK_THAT(rotation->at(t).theta,
             Catch::Matchers::WithinAbs(
                 0.3 * std::sin(2.0 * std::numbers::pi * t / 1.2) + 0.05 * t * t, 1e-4));
  // A two-column table along one direction: d = s(t) direction.
  const TableTranslation along_y(data("motion_rotation.csv"), Vec2(0.0, 2.0));
  CHECK_THAT(along_y.at(0.5).d.y(), Catch::Matchers::WithinRel(2.0 * theta_row, 1e-14));
  CHECK(along_y.at(0.5).d.x() == 0.0);
  CHECK_THAT(along_y.at(0.725).d_dot.y(),
             Catch::Matchers::WithinRel(2.0 * rotation->at(0.725).omega, 1e-14));
  // Degrees scaling.
  const TableRotation degrees(data("motion_rotation.csv"), std::numbers::pi / 180.0);
  CHECK_THAT(degrees.at(0.5).theta,
             Catch::Matchers::WithinRel(theta_row * std::numbers::pi / 180.0, 1e-14));
}

TEST_CASE("erp: CSV tables: a bad line names file and line", "[motion]") {
  const std::string bad = data("motion_bad_line.csv");
  CHECK_THROWS_WITH(TableRotation(bad), Catch::Matchers::StartsWith(bad + ":5: "));
  const std::string decreasing = data("motion_time_decreasing.csv");
  CHECK_THROWS_WITH(TableRotation(decreasing), Catch::Matchers::StartsWith(decreasing + ":3: "));
  CHECK_THROWS_WITH(TableTranslation(data("motion_rotation.csv")),
                    Catch::Matchers::Contains("motion_rotation.csv:3: expected 3 columns"));
  CHECK_THROWS_AS(TableRotation(data("no_such_file.csv")), InputError);
}

TEST_CASE("erp: rigid polyline nodes follow the motion", "[motion]") {
  WallSet walls;
  const std::vector<Vec2> points{{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}};
  const Vec2 pivot(0.5, 0.0);
  const auto motion = std::make_shared<SinusoidRotation>(0.1, 1.0, 0.0);
  walls.add_rigid_polyline(points, false, 3, pivot, motion);
  walls.move_rigid(0.2);
  for (int L = 0; L < 3; ++L) {
    const NodeState s =
        rigid_node_state(motion->at(0.2), pivot, points[static_cast<std::size_t>(L)]);
    CHECK((walls.nodes().x[static_cast<std::size_t>(L)] - s.x).norm() < 1e-15);
    CHECK((walls.nodes().v[static_cast<std::size_t>(L)] - s.v).norm() < 1e-15);
    CHECK((walls.nodes().a[static_cast<std::size_t>(L)] - s.a).norm() < 1e-15);
  }
  // Rigid: the segment length is kept.
  CHECK_THAT((walls.nodes().x[1] - walls.nodes().x[0]).norm(),
             Catch::Matchers::WithinAbs(1.0, 1e-15));
  CHECK(walls.segments().group[0] == 3);
}
