// A dynamic step whose Newton fails is retried as sub-steps (NewtonOptions::max_substep_levels):
// the result is the one of taking those sub-steps by hand, with the loads linear in time.
#include <catch2/catch.hpp>

#include <cmath>

#include "fsi/core/error.hpp"
#include "structure_fem/loads.hpp"
#include "structure_fem/rectangle_mesher.hpp"
#include "structure_fem/structure.hpp"

using namespace fsi::fem;
using Catch::Matchers::WithinAbs;

namespace {

/// A 1 x 0.2 m rubber cantilever (8 x 2 rectangles) clamped on the left, neo-Hookean.
std::unique_ptr<Structure> cantilever(int max_substep_levels) {
  StructureOptions o;
  o.material = {1.0e6, 0.45, 1000.0, PlaneModel::plane_strain, MaterialModel::neo_hookean};
  o.clamped = {{"left", true, true, {}, {}}};
  o.newton.max_iterations = 4;
  o.newton.max_substep_levels = max_substep_levels;
  o.linear_solver.kind = LinearSolverKind::umfpack;
  return std::make_unique<Structure>(make_rectangle_mesh({{0.0, 0.0}, 1.0, 0.2, 8, 2}), o);
}

Vector tip_load(const Structure& s, double q) { // q N/m^2 downward on the right edge
  return edge_traction_forces(s.mesh(), "right", {0.0, -q});
}

} // namespace

TEST_CASE("fem: a step whose Newton fails is retried as sub-steps with the loads linear in time",
          "[structure_fem][newton]") {
  const double dt = 0.02, q = 4.0e4;
  // One step of a sudden large load: Newton needs more than 4 iterations.
  auto plain = cantilever(0);
  plain->set_external_forces(tip_load(*plain, q));
  CHECK_THROWS_WITH(plain->advance(dt), Catch::Contains("Newton did not converge in 4"));
  CHECK(plain->time() == 0.0); // the state is unchanged

  auto retried = cantilever(3);
  retried->set_external_forces(tip_load(*retried, q));
  const StepReport report = retried->advance(dt);
  REQUIRE(report.substeps > 1);
  CHECK(retried->step() == 1);
  CHECK(retried->time() == dt);

  // The same sub-steps by hand: forces f^n + (f^{n+1} - f^n) i / n at the end of sub-step i.
  auto by_hand = cantilever(0);
  const int n = report.substeps;
  for (int i = 1; i <= n; ++i) {
    by_hand->set_external_forces(tip_load(*by_hand, q * i / n));
    by_hand->advance(dt / n);
  }
  const Vector& u = retried->displacement();
  const double tip = u.cwiseAbs().maxCoeff();
  CHECK(tip > 0.01); // a large step: centimetres in 0.02 s
  CHECK((u - by_hand->displacement()).cwiseAbs().maxCoeff() < 1e-12 * tip);
  CHECK((retried->velocity() - by_hand->velocity()).cwiseAbs().maxCoeff() <
        1e-9 * by_hand->velocity().cwiseAbs().maxCoeff());
}
