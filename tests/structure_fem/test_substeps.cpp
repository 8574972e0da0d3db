// A dynamic step whose Newton fails is retried as sub-steps (NewtonOptions::max_substep_levels):
// the result is the one of taking those sub-steps by hand, with the loads linear in time.
#include <catch2/catch.hpp>

#include "structure_fem/loads.hpp"
#include "structure_fem/rectangle_mesher.hpp"
#include "structure_fem/structure.hpp"
#include "substeps.hpp"

using namespace fsi::fem;

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
  fem_test::check_substeps_by_hand(cantilever, tip_load, 0.02, 4.0e4);
}
