// Smoothed-aggregation multigrid (structure_fem/smoothed_aggregation.hpp) as CG's preconditioner
// on the static stiffness of a clamped T10 beam: the V-cycle is symmetric positive definite, and
// CG's iterations do not grow with the mesh as CG + Jacobi's do (h^-1).
#include <catch2/catch.hpp>

#include <random>
#include <sstream>
#include <vector>

#include "structure_fem/assembly.hpp"
#include "structure_fem/box_mesher.hpp"
#include "structure_fem/linear_solver.hpp"
#include "structure_fem/loads.hpp"
#include "structure_fem/smoothed_aggregation.hpp"

using namespace fsi::fem;

namespace {

/// A 1 x 0.25 x 0.25 steel beam of nx x nx/4 x nx/4 cells (6 T10 each) clamped at x_min: its
/// linear stiffness K (u = 0), a shear end load f, and the rigid-body modes of its free dofs.
struct StaticBeam {
  TetMesh mesh;
  std::unique_ptr<Material3> law = make_material_3d({2.0e11, 0.3, 7800.0});
  DofMap dofs;
  SparseMatrix K;
  Vector f;
  NearNullSpace modes;
  explicit StaticBeam(int nx)
      : mesh(make_box_mesh({{0.0, 0.0, 0.0}, {1.0, 0.25, 0.25}, {nx, nx / 4, nx / 4}})),
        dofs(mesh, {{"x_min", {true, true, true}, {}}}) {
    AssemblerT10 assembler(mesh, *law, dofs);
    Vector f_int;
    K = assembler.pattern();
    assembler.assemble(Vector::Zero(3 * static_cast<Eigen::Index>(mesh.num_nodes())), f_int, &K);
    f = dofs.restrict_to_free(face_traction_forces(
        mesh, "x_max", [](const fsi::Vec3&) { return fsi::Vec3(0.0, 0.0, -1.0e6); }));
    modes = rigid_body_modes<3>(dofs, mesh.X);
  }
  /// CG iterations to 1e-10 with `kind`, levels down to `coarse_size` dofs for cg_amg.
  int iterations(LinearSolverKind kind, int coarse_size) const {
    const auto solver = make_linear_solver({kind, 1e-10, 0, coarse_size});
    solver->set_near_null_space(modes);
    solver->analyze(K);
    solver->factorize(K);
    solver->solve(f);
    return solver->iterations();
  }
};

} // namespace

TEST_CASE("smoothed aggregation: the V-cycle is symmetric positive definite",
          "[structure_fem][t10][linear_solver][amg]") {
  const StaticBeam beam(8);
  SmoothedAggregationOptions options;
  options.coarse_size = 100;
  SmoothedAggregation amg(options);
  amg.setup(beam.K, beam.modes);
  REQUIRE(amg.level_sizes().size() >= 3); // smoothers, transfers and the coarse solve all act
  std::mt19937 generator(7);
  std::normal_distribution<double> normal;
  const auto n = beam.K.rows();
  Vector Mx(n), My(n);
  for (int trial = 0; trial < 3; ++trial) {
    const Vector x = Vector::NullaryExpr(n, [&]() { return normal(generator); });
    const Vector y = Vector::NullaryExpr(n, [&]() { return normal(generator); });
    amg.apply(x, Mx);
    amg.apply(y, My);
    CHECK(std::abs(x.dot(My) - y.dot(Mx)) <= 1e-13 * x.norm() * My.norm());
    CHECK(x.dot(Mx) > 0.0);
  }
}

TEST_CASE("smoothed aggregation: CG's iterations do not grow with the mesh",
          "[structure_fem][t10][linear_solver][amg]") {
  // Three levels or more on both meshes (coarsest at most 200 dofs): h halves from nx = 8 to 16.
  const int coarse = StaticBeam(8).iterations(LinearSolverKind::cg_amg, 200);
  const int fine = StaticBeam(16).iterations(LinearSolverKind::cg_amg, 200);
  WARN("cg_amg: " << coarse << " -> " << fine << " iterations");
  CHECK(fine <= 1.5 * coarse);
}

TEST_CASE("smoothed aggregation against Jacobi: iterations at h, h/2, h/3",
          "[structure_fem][t10][linear_solver][amg][slow]") {
  // CG + Jacobi's iterations grow as h^-1, the multigrid's do not (the library's coarse size).
  std::vector<int> amg, jacobi;
  std::ostringstream log;
  for (const int nx : {8, 16, 24}) {
    const StaticBeam beam(nx);
    amg.push_back(beam.iterations(LinearSolverKind::cg_amg, 2000));
    jacobi.push_back(beam.iterations(LinearSolverKind::cg_jacobi, 2000));
    log << beam.dofs.num_free() << " free dofs: cg_amg " << amg.back() << ", cg_jacobi "
        << jacobi.back() << " iterations; ";
  }
  WARN(log.str());
  CHECK(amg[2] <= 1.5 * amg[1]);
  CHECK(jacobi[2] >= 1.3 * jacobi[1]); // h^-1 would be 1.5
  CHECK(amg[2] * 10 < jacobi[2]);
}

TEST_CASE("smoothed aggregation: a hierarchy kept across Newton iterations",
          "[structure_fem][t10][linear_solver][amg]") {
  // K1: the beam's stiffness at u = 0; K2: its tangent at the linear solution scaled by s (tip
  // deflection about s * 3.2e-4 m: stressed and rotated, what a later Newton iteration sees).
  const StaticBeam beam(8);
  AssemblerT10 assembler(beam.mesh, *beam.law, beam.dofs);
  const auto direct = make_linear_solver({LinearSolverKind::cholmod});
  direct->analyze(beam.K);
  direct->factorize(beam.K);
  const Vector u_linear = direct->solve(beam.f);
  auto tangent = [&](double s) {
    Vector u = Vector::Zero(beam.dofs.num_dofs()), f_int;
    beam.dofs.add_free(s * u_linear, u);
    SparseMatrix K = assembler.pattern();
    assembler.assemble(u, f_int, &K);
    return K;
  };
  // CG on K1, then on K2, with the hierarchy rebuilt (0) or kept while within `ratio`.
  struct Run {
    int first, second;
    long setups;
    double error; // of the K2 solve against CHOLMOD's
  };
  auto run = [&](double ratio, const SparseMatrix& K2) {
    LinearSolverOptions o{LinearSolverKind::cg_amg, 1e-10, 0, 200};
    o.amg_rebuild_ratio = ratio;
    const auto amg = make_linear_solver(o);
    amg->set_near_null_space(beam.modes);
    amg->analyze(beam.K);
    amg->factorize(beam.K);
    amg->solve(beam.f);
    Run r{amg->iterations(), 0, 0, 0.0};
    amg->factorize(K2);
    const Vector x = amg->solve(beam.f);
    r.second = amg->iterations();
    r.setups = amg->setups();
    direct->factorize(K2);
    const Vector exact = direct->solve(beam.f);
    r.error = (x - exact).norm() / exact.norm();
    return r;
  };
  const SparseMatrix K2 = tangent(100.0);
  const Run rebuilt = run(0.0, K2), kept = run(1.5, K2);
  WARN("K2 at 100x the linear state: rebuilt " << rebuilt.first << " -> " << rebuilt.second
                                               << " iterations, kept " << kept.first << " -> "
                                               << kept.second);
  CHECK(rebuilt.setups == 2);
  CHECK(kept.setups == 1);
  CHECK(kept.second <= 1.5 * kept.first);
  CHECK(rebuilt.error < 1e-8);
  CHECK(kept.error < 1e-8); // a lagged preconditioner, the same answer

  // Far from K1 (1000x: about 0.3 m on the 1 m beam) the kept hierarchy needs more iterations
  // than its first solve; with ratio 1 that marks it stale and the next factorize rebuilds it.
  const SparseMatrix K3 = tangent(1000.0);
  LinearSolverOptions o{LinearSolverKind::cg_amg, 1e-10, 0, 200};
  o.amg_rebuild_ratio = 1.0;
  const auto amg = make_linear_solver(o);
  amg->set_near_null_space(beam.modes);
  amg->analyze(beam.K);
  amg->factorize(beam.K);
  amg->solve(beam.f);
  const int first = amg->iterations();
  amg->factorize(K3);
  amg->solve(beam.f);
  const int lagged = amg->iterations();
  CHECK(amg->setups() == 1);
  amg->factorize(K3);
  amg->solve(beam.f);
  const Run fresh = run(0.0, K3);
  WARN("K3 at 1000x: " << first << " -> " << lagged << " iterations kept, " << amg->iterations()
                       << " after the rebuild (a fresh hierarchy: " << fresh.second << ")");
  REQUIRE(lagged > first);
  CHECK(amg->setups() == 2);
  CHECK(amg->iterations() == fresh.second);
}
