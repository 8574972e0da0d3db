// A T10 body whose clamp moves rigidly (issue 44: prescribed motions of a clamp). Statically,
// without load, the body follows a translation of the clamp; with gravity g on the body and the
// clamp falling at g, the whole body falls with u = g t^2 / 2 stress-free (equivalence
// principle), which Newmark integrates exactly: the free nodes reach it only if the clamped
// nodes' inertia enters their equations through the consistent mass (as for the T6).
#include <catch2/catch.hpp>

#include "sequential.hpp"
#include "structure_fem/box_mesher.hpp"
#include "structure_fem/structure.hpp"

using namespace fsi::fem;

namespace {

StructureT10Options clamp_moving(PrescribedMotion3 motion, const fsi::Vec3& gravity) {
  StructureT10Options o;
  o.gravity = gravity;
  o.newton.residual_rtol = 1e-12;
  o.material = {1.0e6, 0.3, 1000.0};
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
