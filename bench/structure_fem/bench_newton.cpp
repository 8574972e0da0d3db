// Cost of one Newton iteration of the T6 solid, split into assembly (internal force + tangent),
// factorisation and solve (CHOLMOD; Eigen's SimplicialLDLT factorisation for comparison), or
// preconditioner set-up and CG solve (IncompleteCholesky), for about 200, 2k and 20k elements,
// on 1 and 2 threads (only the assembly loop is parallel).
#include <benchmark/benchmark.h>

#include <map>
#include <memory>
#include <stdexcept>

#include "common/sweep.hpp"
#include "structure_fem/assembly.hpp"
#include "structure_fem/linear_solver.hpp"
#include "structure_fem/rectangle_mesher.hpp"

using namespace fsi::fem;

namespace {

/// A clamped 1 x 0.25 beam in a bent state; K is the effective tangent c0 M + K_T of a Newmark
/// step (beta = 0.3025, dt = 1e-3 s, E = 1e6 Pa, rho = 1000 kg/m^3, as in the dam-break obstacle).
struct Problem {
  Mesh mesh;
  StVenantKirchhoff material{{1.0e6, 0.3, 1000.0, PlaneModel::plane_strain}};
  std::unique_ptr<DofMap> dofs;
  std::unique_ptr<Assembler> assembler;
  SparseMatrix M, K, K_eff;
  Vector u, f, rhs;

  explicit Problem(int ex) {
    mesh = make_rectangle_mesh({{0.0, 0.0}, 1.0, 0.25, ex, ex / 4});
    dofs =
        std::make_unique<DofMap>(mesh, std::vector<DirichletCondition>{{"left", true, true, {}}});
    assembler = std::make_unique<Assembler>(mesh, material, *dofs);
    M = assembler->mass();
    K = K_eff = assembler->pattern();
    u = Vector::Zero(2 * static_cast<Eigen::Index>(mesh.num_nodes()));
    for (std::size_t k = 0; k < mesh.num_nodes(); ++k) {
      const double x = mesh.X[k].x(), y = mesh.X[k].y() - 0.125;
      u[2 * static_cast<Eigen::Index>(k)] = -2e-2 * x * y;
      u[2 * static_cast<Eigen::Index>(k) + 1] = 1e-2 * x * x;
    }
    assembler->assemble(u, f, &K);
    const double beta = 0.3025, dt = 1e-3;
    K_eff = K + (1.0 / (beta * dt * dt)) * M;
    rhs = dofs->restrict_to_free(f);
  }
};

Problem& problem(int ex) {
  static std::map<int, std::unique_ptr<Problem>> cache;
  auto& p = cache[ex];
  if (!p) p = std::make_unique<Problem>(ex);
  return *p;
}

void set_counters(benchmark::State& state, const Problem& p) {
  state.counters["elements"] = static_cast<double>(p.mesh.num_elements());
  state.counters["dofs"] = p.dofs->num_free();
  state.counters["threads"] = static_cast<double>(state.range(1));
}

/// The problem of state.range(0) quads along the beam (ex / 4 across: 20 -> 200, 64 -> 2048,
/// 200 -> 20000 elements), on state.range(1) threads.
Problem& setup(benchmark::State& state) {
  Problem& p = problem(static_cast<int>(state.range(0)));
  fsi::bench::use_threads(state, 1);
  return p;
}

void BM_Assembly(benchmark::State& state) {
  Problem& p = setup(state);
  Vector f;
  for (auto _ : state) {
    p.assembler->assemble(p.u, f, &p.K);
    benchmark::DoNotOptimize(p.K.valuePtr());
  }
  set_counters(state, p);
}

/// The factorisation of K_eff (CG: the preconditioner set-up).
void BM_Factorize(benchmark::State& state, LinearSolverKind kind) {
  Problem& p = setup(state);
  auto solver = make_linear_solver({kind, 1e-10, 0});
  solver->analyze(p.K_eff);
  for (auto _ : state) solver->factorize(p.K_eff);
  set_counters(state, p);
}

void BM_Solve(benchmark::State& state, LinearSolverKind kind) {
  Problem& p = setup(state);
  auto solver = make_linear_solver({kind, 1e-10, 0});
  solver->analyze(p.K_eff);
  solver->factorize(p.K_eff);
  for (auto _ : state) benchmark::DoNotOptimize(solver->solve(p.rhs));
  set_counters(state, p);
  if (kind == LinearSolverKind::cg_incomplete_cholesky)
    state.counters["cg_iterations"] = solver->iterations();
}

constexpr auto sizes = fsi::bench::sizes_on_1_and_2_threads<20, 64, 200>;

} // namespace

BENCHMARK(BM_Assembly)->Apply(sizes);
BENCHMARK_CAPTURE(BM_Factorize, cholmod, LinearSolverKind::cholmod)->Apply(sizes);
BENCHMARK_CAPTURE(BM_Solve, cholmod, LinearSolverKind::cholmod)->Apply(sizes);
BENCHMARK_CAPTURE(BM_Factorize, simplicial_ldlt, LinearSolverKind::simplicial_ldlt)->Apply(sizes);
BENCHMARK_CAPTURE(BM_Factorize, cg_incomplete_cholesky, LinearSolverKind::cg_incomplete_cholesky)
    ->Apply(sizes);
BENCHMARK_CAPTURE(BM_Solve, cg_incomplete_cholesky, LinearSolverKind::cg_incomplete_cholesky)
    ->Apply(sizes);

BENCHMARK_MAIN();
