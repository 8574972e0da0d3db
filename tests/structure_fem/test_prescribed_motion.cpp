// Prescribed time-dependent Dirichlet conditions (a structure clamped to a moving tank): the
// clamped nodes follow u(t), v(t), a(t) exactly, and rigid motions leave an unloaded body
// stress-free.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "fsi/core/parallel.hpp"
#include "sequential.hpp"
#include "structure_fem/rectangle_mesher.hpp"
#include "structure_fem/structure.hpp"

using namespace fsi;
using namespace fsi::fem;

namespace {

Mesh strip_mesh() {
  RectangleMeshOptions r;
  r.origin = {0.2, 0.1};
  r.width = 0.5, r.height = 0.1, r.elements_x = 10, r.elements_y = 2;
  return make_rectangle_mesh(r);
}

StructureOptions rubber_strip() {
  StructureOptions o;
  o.material.youngs_modulus = 3.3e6;
  o.material.poisson_ratio = 0.3;
  o.material.density = 1100.0;
  return o;
}

double max_abs(const Vector& x) {
  return x.cwiseAbs().maxCoeff();
}

} // namespace

TEST_CASE("fem: a body whose clamped edge falls freely falls with it, stress-free",
          "[structure_fem][prescribed]") {
  // Gravity g on the body and u = g t^2 / 2 on the clamped edge: the whole body then falls
  // with u = g t^2 / 2 and no strain (equivalence principle). The free nodes reach it only if
  // the clamped nodes' inertia enters their equations through the consistent mass (M_fc a_c),
  // and Newmark integrates a constant acceleration exactly for any beta, gamma.
  const fem_test::Sequential sequential;
  const Vec2 g(0.3, -9.81);
  StructureOptions o = rubber_strip();
  o.gravity = g;
  o.clamped = {{"left", true, true, {}, [g](const Vec2&, double t) {
                  return PrescribedKinematics{0.5 * t * t * g, t * g, g};
                }}};
  Structure s(strip_mesh(), o);
  const double dt = 2e-3;
  for (int i = 0; i < 50; ++i) s.advance(dt);
  const double t = s.time();
  REQUIRE(t == Approx(0.1));
  Vector u_exact(s.displacement().size()), v_exact(u_exact.size()), a_exact(u_exact.size());
  for (Eigen::Index k = 0; k < u_exact.size() / 2; ++k) {
    u_exact.segment<2>(2 * k) = 0.5 * t * t * g;
    v_exact.segment<2>(2 * k) = t * g;
    a_exact.segment<2>(2 * k) = g;
  }
  CHECK(max_abs(s.displacement() - u_exact) < 1e-12);
  CHECK(max_abs(s.velocity() - v_exact) < 1e-10);
  CHECK(max_abs(s.acceleration() - a_exact) < 1e-7);
  CHECK(max_abs(s.von_mises()) < 1e-3); // Pa, against E = 3.3e6 Pa
}

TEST_CASE("fem: without the clamped inertia a falling body would strain (the test can fail)",
          "[structure_fem][prescribed]") {
  // Same fall, but the edge is held in place: the body hangs and strains. Guards the test above
  // against passing trivially.
  const fem_test::Sequential sequential;
  StructureOptions o = rubber_strip();
  o.gravity = {0.3, -9.81};
  o.clamped = {{"left", true, true, {}}};
  Structure s(strip_mesh(), o);
  for (int i = 0; i < 50; ++i) s.advance(2e-3);
  CHECK(max_abs(s.von_mises()) > 1e3);
}

TEST_CASE("fem: a large rigid rotation prescribed on the clamped edge turns the body rigidly",
          "[structure_fem][prescribed]") {
  // Static, 60 degrees about c: every node ends at c + R (X - c) and St. Venant–Kirchhoff gives
  // zero stress (E = 0 for F = R). The edge's displacement is applied in load steps.
  const fem_test::Sequential sequential;
  const Vec2 c(0.1, 0.05);
  const double theta_end = std::numbers::pi / 3.0;
  auto rotation = [](double theta) {
    Mat2 R;
    R << std::cos(theta), -std::sin(theta), std::sin(theta), std::cos(theta);
    return R;
  };
  StructureOptions o = rubber_strip();
  o.clamped = {{"left", true, true, {}, [&](const Vec2& X, double t) {
                  return PrescribedKinematics{(rotation(theta_end * t) - Mat2::Identity()) *
                                                  (X - c),
                                              Vec2::Zero(), Vec2::Zero()};
                }}};
  Structure s(strip_mesh(), o);
  StaticOptions so;
  so.load_steps = 6;
  so.time = 1.0;
  s.solve_static(so);
  CHECK(s.time() == 1.0);
  const auto x = s.positions();
  double error = 0.0;
  for (std::size_t k = 0; k < x.size(); ++k)
    error = std::max(error, (x[k] - (c + rotation(theta_end) * (s.mesh().X[k] - c))).norm());
  CHECK(error < 1e-9); // m, on a 0.5 m body
  CHECK(max_abs(s.von_mises()) < 1e-2);
}

TEST_CASE("fem: clamped dofs carry the prescribed u, v, a after each step and in the predictor",
          "[structure_fem][prescribed]") {
  // A roller (x only) on the left edge oscillating in x; y stays free there.
  const fem_test::Sequential sequential;
  const double A = 0.01, w = 2.0 * std::numbers::pi / 0.4;
  StructureOptions o = rubber_strip();
  o.gravity = {0.0, -9.81};
  o.clamped = {{"left", true, false, {}, [&](const Vec2&, double t) {
                  return PrescribedKinematics{{A * std::sin(w * t), 7.0},
                                              {A * w * std::cos(w * t), 7.0},
                                              {-A * w * w * std::sin(w * t), 7.0}};
                }}};
  Structure s(strip_mesh(), o);
  const auto left = s.mesh().node_set("left");
  const double dt = 1e-3;
  for (int i = 0; i < 30; ++i) {
    const Prediction p = s.predict(dt);
    s.advance(dt);
    const double t = s.time();
    for (int k : left) {
      CHECK(p.u[2 * k] == s.displacement()[2 * k]);
      CHECK(s.displacement()[2 * k] == A * std::sin(w * t));
      CHECK(s.velocity()[2 * k] == A * w * std::cos(w * t));
      CHECK(s.acceleration()[2 * k] == -A * w * w * std::sin(w * t));
      CHECK(s.displacement()[2 * k + 1] != 7.0); // y is free on a roller
    }
  }
  // Restoring and re-running a step reproduces it (the motion is a function of time only).
  const StructureState saved = s.save();
  s.advance(dt);
  const Vector u1 = s.displacement();
  s.restore(saved);
  s.advance(dt);
  CHECK(max_abs(s.displacement() - u1) == 0.0);
}
