// StructureT10 through the code it shares with the T6 (issue 44): a step whose Newton fails is
// retried as sub-steps with the loads linear in time and equals those sub-steps taken by hand; a
// step whose tangent at eq. 64's guess is indefinite is solved from u^n + dt v^n;
// save/restore and a checkpoint (write_state, read_state into a new structure) mid-run continue
// bit for bit as the uninterrupted run.
#include <catch2/catch.hpp>

#include <memory>
#include <string>

#include "fsi/core/state_archive.hpp"
#include "structure_fem/box_mesher.hpp"
#include "structure_fem/loads.hpp"
#include "structure_fem/structure.hpp"
#include "substeps.hpp"

using namespace fsi::fem;

namespace {

/// A 1 x 0.2 x 0.2 m rubber cantilever (4 x 1 x 1 cells) clamped on x_min, neo-Hookean.
std::unique_ptr<StructureT10> cantilever_t10(int max_substep_levels) {
  StructureT10Options o;
  o.material = {1.0e6, 0.45, 1000.0, PlaneModel::plane_strain, MaterialModel::neo_hookean};
  o.clamped = {{"x_min", {true, true, true}, {}, {}}};
  o.newton.max_iterations = 4;
  o.newton.max_substep_levels = max_substep_levels;
  return std::make_unique<StructureT10>(
      make_box_mesh({{0.0, 0.0, 0.0}, {1.0, 0.2, 0.2}, {4, 1, 1}}), o);
}

Vector tip_load_t10(const StructureT10& s, double q) { // q N/m^2 downward on face x_max
  return face_traction_forces(s.mesh(), "x_max",
                              [&](const fsi::Vec3&) { return fsi::Vec3(0.0, 0.0, -q); });
}

} // namespace

TEST_CASE("T10: a step whose Newton fails is retried as sub-steps with the loads linear in time",
          "[structure_fem][t10][newton]") {
  fem_test::check_substeps_by_hand(cantilever, tip_load, 0.02, 4.0e4);
}

TEST_CASE("T10: a sudden load whose eq. 64 guess has an indefinite tangent is solved from u^n + "
          "dt v^n",
          "[structure_fem][t10][newton]") {
  // The 3-D hydrostatic plate's aluminium (1 x 0.05 x 1 m, clamped sides, 4905 Pa on top) in
  // 4 x 4 x 4 cells of aspect 20: the consistent mass gives an initial acceleration of about
  // 1e3 m/s^2 that oscillates through the thickness, and dt^2 a^0 / 2 strains the thin layers so
  // much that K_eff at that guess is not positive definite (CHOLMOD refuses it; LU solves it).
  auto plate = [](LinearSolverKind kind) {
    StructureT10Options o;
    o.material = {6.75e10, 0.34, 2700.0, PlaneModel::plane_strain,
                  MaterialModel::saint_venant_kirchhoff};
    for (const char* side : {"x_min", "x_max", "z_min", "z_max"})
      o.clamped.push_back({side, {true, true, true}, {}, {}});
    o.linear_solver.kind = kind;
    auto s = std::make_unique<StructureT10>(
        make_box_mesh({{0.0, -0.05, 0.0}, {1.0, 0.05, 1.0}, {4, 4, 4}}), o);
    s->set_external_forces(
        face_pressure_forces(s->mesh(), "y_max", [](const fsi::Vec3&) { return 4905.0; }));
    s->update_acceleration();
    return s;
  };
  auto cholmod = plate(LinearSolverKind::cholmod), lu = plate(LinearSolverKind::umfpack);
  const double dt = 1.0e-3;
  const auto retried = cholmod->advance(dt);
  const auto direct = lu->advance(dt);
  CHECK(retried.guess_retries == 1); // eq. 64's guess failed with CHOLMOD
  CHECK(direct.guess_retries == 0);  // LU converged from it
  const double u = lu->displacement().cwiseAbs().maxCoeff();
  const double diff = (cholmod->displacement() - lu->displacement()).cwiseAbs().maxCoeff();
  WARN("retried from u^n + dt v^n: largest |u| " << u << " m, difference from LU " << diff
                                                 << " m, Newton " << retried.iterations << " / "
                                                 << direct.iterations << " iterations");
  CHECK(u > 1e-6);
  CHECK(diff < 1e-8 * u);
}

TEST_CASE("T10: save/restore and a checkpoint mid-run continue bit for bit",
          "[structure_fem][t10][checkpoint]") {
  const double dt = 0.005, q = 5.0e3;
  const int steps = 8, middle = 4;
  auto run = [&](StructureT10& s, int count) {
    for (int i = 0; i < count; ++i) s.advance(dt);
  };
  auto reference = cantilever_t10(3);
  reference->set_external_forces(tip_load_t10(*reference, q));
  run(*reference, steps);

  // save, two steps, restore, and the same steps again: the re-run of iterative coupling.
  auto rerun = cantilever_t10(3);
  rerun->set_external_forces(tip_load_t10(*rerun, q));
  run(*rerun, middle);
  const StructureState saved = rerun->save();
  run(*rerun, 2);
  rerun->restore(saved);
  rerun->set_external_forces(tip_load_t10(*rerun, q));
  run(*rerun, steps - middle);

  // Checkpoint written mid-run and read into a new structure.
  auto first = cantilever_t10(3);
  first->set_external_forces(tip_load_t10(*first, q));
  run(*first, middle);
  fsi::StateArchive archive;
  first->write_state(archive, "solid.");
  auto resumed = cantilever_t10(3);
  resumed->read_state(archive, "solid.");
  run(*resumed, steps - middle);

  const double moved = reference->displacement().cwiseAbs().maxCoeff();
  WARN("T10 checkpoint: largest |u| after " << steps << " steps " << moved << " m");
  REQUIRE(moved > 1e-4);
  for (const StructureT10* s : {rerun.get(), resumed.get()}) {
    CHECK(s->step() == reference->step());
    CHECK(s->time() == reference->time());
    CHECK(s->displacement() == reference->displacement());
    CHECK(s->velocity() == reference->velocity());
    CHECK(s->acceleration() == reference->acceleration());
    CHECK(s->energies().total() == reference->energies().total());
  }
}
