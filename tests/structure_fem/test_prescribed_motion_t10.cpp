// A T10 body whose clamp moves rigidly (issue 44: prescribed motions of a clamp). Statically,
// without load, the body follows a translation or a finite rotation of the clamp (F = R: E = 0,
// zero stress for both laws); with gravity g on the body and the
// clamp falling at g, the whole body falls with u = g t^2 / 2 stress-free (equivalence
// principle), which Newmark integrates exactly: the free nodes reach it only if the clamped
// nodes' inertia enters their equations through the consistent mass (as for the T6).
#include <Eigen/Geometry>
#include <catch2/catch.hpp>

#include <memory>
#include <numbers>

#include "sequential.hpp"
#include "structure_fem/box_mesher.hpp"
#include "structure_fem/structure.hpp"

using namespace fsi::fem;

namespace {

StructureT10Options clamp_moving(PrescribedMotion3 motion, const fsi::Vec3& gravity,
                                 MaterialModel model = MaterialModel::saint_venant_kirchhoff) {
  StructureT10Options o;
  o.gravity = gravity;
  o.newton.residual_rtol = 1e-12;
  o.material = {1.0e6, 0.3, 1000.0};
  o.material.model = model;
  o.newmark = {0.25, 0.5};
  o.clamped = {{"x_min", {true, true, true}, {}, std::move(motion)}};
  return o;
}

/// Largest |u_K - u| over the nodes.
double largest_deviation(const Vector& u_nodes, const fsi::Vec3& u) {
  double worst = 0.0;
  for (Eigen::Index k = 0; k < u_nodes.size() / 3; ++k)
    worst = std::max(worst, (u_nodes.segment<3>(3 * k) - u).norm());
  return worst;
}

/// Rotation by theta about the unit axis a (Rodrigues), counter-clockwise seen from the tip of a.
fsi::Mat3 rotation(const fsi::Vec3& a, double theta) {
  return Eigen::AngleAxisd(theta, a).toRotationMatrix();
}

/// The box 1 x 0.2 x 0.2 with its x_min face turned statically by theta about the axis a through
/// c, the face's centre, in `steps` load steps: no load, so every node should end at
/// c + R (X - c). Returns the solved structure.
std::unique_ptr<StructureT10> turned(const fsi::Vec3& a, double theta, MaterialModel model,
                                     int steps) {
  const fsi::Vec3 c(0.0, 0.1, 0.1);
  auto s = std::make_unique<StructureT10>(
      make_box_mesh({{0.0, 0.0, 0.0}, {1.0, 0.2, 0.2}, {4, 1, 1}}),
      clamp_moving(
          [a, theta, c](const fsi::Vec3& X, double t) {
            const fsi::Mat3 R = rotation(a, theta * t);
            return PrescribedKinematics3{(R - fsi::Mat3::Identity()) * (X - c), fsi::Vec3::Zero(),
                                         fsi::Vec3::Zero()};
          },
          fsi::Vec3::Zero(), model));
  s->solve_static({steps, 1.0});
  return s;
}

/// Largest |x_K - (c + R (X_K - c))| over the nodes.
double rigid_deviation(const StructureT10& s, const fsi::Mat3& R, const fsi::Vec3& c) {
  const auto x = s.positions();
  double worst = 0.0;
  for (std::size_t k = 0; k < x.size(); ++k)
    worst = std::max(worst, (x[k] - (c + R * (s.mesh().X[k] - c))).norm());
  return worst;
}

/// The displacement of the node at X (a node of the mesh).
fsi::Vec3 displacement_at(const StructureT10& s, const fsi::Vec3& X) {
  for (std::size_t k = 0; k < s.mesh().num_nodes(); ++k)
    if ((s.mesh().X[k] - X).norm() < 1e-12)
      return s.displacement().segment<3>(3 * static_cast<Eigen::Index>(k));
  FAIL("no node at " << X.transpose());
  return {};
}

} // namespace

TEST_CASE("T10 prescribed motion: the body follows a rigid translation of its clamp",
          "[structure_fem][t10][prescribed]") {
  const fem_test::Sequential sequential;
  const TetMesh mesh = make_box_mesh({{0.0, 0.0, 0.0}, {1.0, 0.2, 0.2}, {4, 1, 1}});
  const fsi::Vec3 d(0.01, -0.02, 0.03);
  StructureT10 still(mesh, clamp_moving(
                               [&](const fsi::Vec3&, double t) {
                                 return PrescribedKinematics3{t * d, d, fsi::Vec3::Zero()};
                               },
                               fsi::Vec3::Zero()));
  still.solve_static({1, 1.0}); // the clamp displaced by d at t = 1
  const double static_deviation = largest_deviation(still.displacement(), d);
  WARN("T10 clamp translated by |d| = " << d.norm() << " m: largest deviation " << static_deviation
                                        << " m");
  CHECK(static_deviation < 1e-10 * d.norm());

  const fsi::Vec3 g(0.5, 0.0, -9.81); // gravity and the clamp's acceleration [m/s^2]
  StructureT10 moving(mesh, clamp_moving(
                                [&](const fsi::Vec3&, double t) {
                                  return PrescribedKinematics3{0.5 * t * t * g, t * g, g};
                                },
                                g));
  for (int n = 0; n < 20; ++n) moving.advance(0.01);
  const double t = moving.time();
  const double deviation = largest_deviation(moving.displacement(), 0.5 * t * t * g);
  WARN("T10 body and clamp falling at |g| = " << g.norm() << " m/s^2 for " << t
                                              << " s: largest deviation from the rigid motion "
                                              << deviation << " m");
  CHECK(deviation < 1e-10 * 0.5 * t * t * g.norm());
  CHECK(largest_deviation(moving.velocity(), t * g) < 1e-10 * t * g.norm());
}

TEST_CASE("T10 prescribed motion: a finite rotation of the clamp turns the body rigidly, "
          "stress-free",
          "[structure_fem][t10][prescribed]") {
  // 60 degrees about the transverse axis y through the clamped face's centre: F = R at every
  // point, so E = 0 and S = 0 for St. Venant-Kirchhoff and neo-Hookean alike (objectivity).
  const fem_test::Sequential sequential;
  const fsi::Vec3 c(0.0, 0.1, 0.1), y(0.0, 1.0, 0.0);
  const double theta = std::numbers::pi / 3.0, E = 1.0e6;
  for (const MaterialModel model :
       {MaterialModel::saint_venant_kirchhoff, MaterialModel::neo_hookean}) {
    const auto s = turned(y, theta, model, 6);
    CHECK(s->time() == 1.0);
    const double deviation = rigid_deviation(*s, rotation(y, theta), c);
    const double stress = s->von_mises().cwiseAbs().maxCoeff();
    WARN("T10 clamp turned 60 degrees about y ("
         << (model == MaterialModel::neo_hookean ? "neo-Hookean" : "St. Venant-Kirchhoff")
         << "): largest deviation from c + R (X - c) " << deviation << " m; largest von Mises / E "
         << stress / E);
    CHECK(deviation < 1e-12); // m, on a 1 m body whose tip moves 1 m
    CHECK(stress < 1e-9 * E);
  }
}

TEST_CASE("T10 prescribed motion: the body turns the way the clamp's rotation says",
          "[structure_fem][t10][prescribed]") {
  // A small positive angle about +y carries the tip (X - c = (L, 0, 0)) to -z, about +z to +y
  // (right-hand rule): u_tip = (R - I)(L, 0, 0) = L (cos theta - 1, 0, -sin theta) and
  // L (cos theta - 1, sin theta, 0).
  const fem_test::Sequential sequential;
  const double theta = 0.01, L = 1.0;
  const fsi::Vec3 tip(L, 0.1, 0.1);
  const fsi::Vec3 about_y = displacement_at(
      *turned({0.0, 1.0, 0.0}, theta, MaterialModel::saint_venant_kirchhoff, 1), tip);
  const fsi::Vec3 about_z = displacement_at(
      *turned({0.0, 0.0, 1.0}, theta, MaterialModel::saint_venant_kirchhoff, 1), tip);
  WARN("T10 clamp turned +0.01 rad: tip u about y " << about_y.transpose() << ", about z "
                                                    << about_z.transpose() << " m");
  CHECK(about_y.z() < -0.99 * L * theta);
  CHECK(about_z.y() > 0.99 * L * theta);
  CHECK((about_y - L * fsi::Vec3(std::cos(theta) - 1.0, 0.0, -std::sin(theta))).norm() < 1e-12);
  CHECK((about_z - L * fsi::Vec3(std::cos(theta) - 1.0, std::sin(theta), 0.0)).norm() < 1e-12);
}
