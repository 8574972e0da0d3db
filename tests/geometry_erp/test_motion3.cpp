// Rigid motions of 3-D walls (motion3.hpp): a rotation about an oblique axis matches Eigen's
// AngleAxis, and v, a are the time derivatives of x (central differences, second order); a
// RigidTriangles3 moves a box tank's nodes and its normals turn with them.
#include "geometry_erp/box_walls.hpp"
#include "geometry_erp/motion3.hpp"

#include <catch2/catch.hpp>

#include <numbers>

using namespace fsi;
using namespace fsi::erp;

namespace {

struct FdErrors3 {
  double v, a;
};

FdErrors3 fd_errors3(const RigidMotion3& m, const Vec3& X, double t, double h) {
  const auto x = [&](double s) { return m.at(s, X).x; };
  const NodeState3 exact = m.at(t, X);
  const Vec3 v_fd = (x(t + h) - x(t - h)) / (2.0 * h);
  const Vec3 a_fd = (x(t + h) - 2.0 * x(t) + x(t - h)) / (h * h);
  return {(v_fd - exact.v).norm(), (a_fd - exact.a).norm()};
}

} // namespace

TEST_CASE("erp: 3-D rigid motions: positions exact, v and a the derivatives of x", "[motion]") {
  const auto profile = std::make_shared<SinusoidRotation>(0.6, 1.3, 0.2); // theta(t), rad
  const Vec3 axis(1.0, -2.0, 0.5), pivot(0.3, 0.1, -0.4), X(1.1, 0.7, -0.2);
  const RigidMotion3 rotation = RigidMotion3::rotation(profile, 3.0 * axis, pivot);
  const auto translation = RigidMotion3::translation(
      std::make_shared<SinusoidTranslation>(Vec2(0.05, 0.0), 0.9, 0.4), Vec3(0.0, 0.6, 0.8));
  for (const double t : {0.0, 0.37, 1.9}) {
    const double theta = profile->at(t).theta;
    const Vec3 expected =
        pivot + Eigen::AngleAxisd(theta, axis.normalized()).toRotationMatrix() * (X - pivot);
    CHECK((rotation.at(t, X).x - expected).norm() < 1e-15);
    CHECK((rotation.at(t, pivot + 2.0 * axis).x - (pivot + 2.0 * axis)).norm() < 1e-15);
    const double s = 0.05 * std::sin(2.0 * std::numbers::pi * t / 0.9 + 0.4);
    CHECK((translation.at(t, X).x - (X + s * Vec3(0.0, 0.6, 0.8))).norm() < 1e-15);
    for (const RigidMotion3* m : {&rotation, &translation}) {
      const FdErrors3 coarse = fd_errors3(*m, X, t, 1e-2), fine = fd_errors3(*m, X, t, 5e-3);
      CHECK(coarse.v > 1e-9);
      CHECK(coarse.a > 1e-9);
      CHECK_THAT(coarse.v / fine.v, Catch::Matchers::WithinAbs(4.0, 0.05));
      CHECK_THAT(coarse.a / fine.a, Catch::Matchers::WithinAbs(4.0, 0.05));
    }
  }
}

TEST_CASE("erp: a box tank of triangles turned a quarter about z: nodes and normals follow",
          "[motion]") {
  TriangleWallSet walls;
  add_box_tank(walls, Vec3::Zero(), Vec3(1.0, 2.0, 3.0), false, 0);
  const auto quarter = std::make_shared<SinusoidRotation>(std::numbers::pi / 2, 4.0, 0.0);
  const RigidTriangles3 tank{RigidMotion3::rotation(quarter, Vec3::UnitZ(), Vec3::Zero()), 0,
                             walls.nodes().x};
  tank.move(walls, 1.0); // theta = pi/2: (x, y, z) -> (-y, x, z), at rest (omega = 0)
  for (std::size_t k = 0; k < tank.reference.size(); ++k) {
    const Vec3& X = tank.reference[k];
    CHECK((walls.nodes().x[k] - Vec3(-X.y(), X.x(), X.z())).norm() < 1e-15);
    CHECK(walls.nodes().v[k].norm() < 1e-15);
  }
  int floor = 0, facing_minus_x = 0;
  for (int t = 0; t < 12; ++t) {
    floor += (walls.face_normal(t) - Vec3::UnitZ()).norm() < 1e-15;
    facing_minus_x += (walls.face_normal(t) + Vec3::UnitX()).norm() < 1e-15; // was the y = 0 face
  }
  CHECK(floor == 2);
  CHECK(facing_minus_x == 2);
}
