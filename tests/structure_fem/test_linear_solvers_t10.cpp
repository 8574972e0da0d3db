// The linear solvers on a 3-D elasticity matrix (issue 44: CG with a preconditioner measured
// against CHOLMOD; cg_amg: smoothed-aggregation multigrid; UMFPACK's LU): each solves K u = f of a
// clamped T10 block under a shear end load to the same answer; the WARN line records their times
// and iterations.
#include <catch2/catch.hpp>

#include <chrono>
#include <sstream>

#include "structure_fem/assembly.hpp"
#include "structure_fem/box_mesher.hpp"
#include "structure_fem/linear_solver.hpp"
#include "structure_fem/loads.hpp"

using namespace fsi::fem;

TEST_CASE("T10 block: CG (incomplete Cholesky, Jacobi, smoothed aggregation) and UMFPACK agree "
          "with CHOLMOD",
          "[structure_fem][t10][linear_solver]") {
  const TetMesh mesh = make_box_mesh({{0.0, 0.0, 0.0}, {1.0, 0.2, 0.2}, {20, 4, 4}});
  const auto law = make_material_3d({2.0e11, 0.3, 7800.0});
  const DofMap dofs(mesh, {{"x_min", {true, true, true}, {}}});
  AssemblerT10 assembler(mesh, *law, dofs);
  Vector f_int;
  SparseMatrix K = assembler.pattern();
  assembler.assemble(Vector::Zero(3 * static_cast<Eigen::Index>(mesh.num_nodes())), f_int, &K);
  const Vector f = dofs.restrict_to_free(face_traction_forces(
      mesh, "x_max", [](const fsi::Vec3&) { return fsi::Vec3(0.0, 0.0, -1.0e6); }));
  std::ostringstream log;
  log << dofs.num_free() << " free dofs, " << K.nonZeros() << " nonzeros:";
  auto solve = [&](LinearSolverKind kind, int& iterations) {
    const auto start = std::chrono::steady_clock::now();
    const auto solver = make_linear_solver({kind, 1e-10, 0});
    solver->set_near_null_space(rigid_body_modes<3>(dofs, mesh.X));
    solver->analyze(K);
    solver->factorize(K);
    Vector u = solver->solve(f);
    iterations = solver->iterations();
    log << " " << to_string(kind) << " "
        << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() << " s ("
        << iterations << " iterations);";
    return u;
  };
  int its = 0;
  const Vector direct = solve(LinearSolverKind::cholmod, its);
  const Vector ic = solve(LinearSolverKind::cg_incomplete_cholesky, its);
  const Vector jacobi = solve(LinearSolverKind::cg_jacobi, its);
  const Vector amg = solve(LinearSolverKind::cg_amg, its);
  const Vector lu = solve(LinearSolverKind::umfpack, its);
  WARN(log.str() << " UMFPACK - CHOLMOD: " << (lu - direct).norm() / direct.norm() << " relative");
  CHECK((ic - direct).norm() <= 1e-8 * direct.norm());
  CHECK((jacobi - direct).norm() <= 1e-8 * direct.norm());
  CHECK((amg - direct).norm() <= 1e-8 * direct.norm());
  CHECK((lu - direct).norm() <= 1e-10 * direct.norm()); // two direct solvers: round-off
}
