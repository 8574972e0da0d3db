// Cost of one Newton iteration of the T10 solid (issue 44), split as bench_newton.cpp splits the
// T6 one: assembly (internal force + tangent), factorisation and solve (CHOLMOD, the 3-D default;
// UMFPACK), or preconditioner set-up and CG solve (incomplete Cholesky, Jacobi), for about 1k,
// 10k and 100k elements on 1 and 2 threads (only the assembly loop is parallel). Counters: the
// free DOFs, CG iterations, the bytes per free DOF of K_eff (values and indices), and the
// process's peak resident set after the factorisation (run one solver and size per process for
// that figure to be the factor's).
#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <map>
#include <memory>

#include "common/sweep.hpp"
#include "structure_fem/assembly.hpp"
#include "structure_fem/box_mesher.hpp"
#include "structure_fem/linear_solver.hpp"

using namespace fsi::fem;

namespace {

/// A 1 x 0.2 x 0.2 beam clamped at x = 0 in a bent state, cubic cells of side 1 / nx split into 6
/// T10 each; K is the effective tangent c0 M + K_T of a Newmark step (beta = 0.3025,
/// dt = 1e-3 s, E = 1e6 Pa, nu = 0.3, rho = 1000 kg/m^3, as bench_newton.cpp's T6 beam).
struct Problem {
  TetMesh mesh;
  std::unique_ptr<Material3> material = make_material_3d({1.0e6, 0.3, 1000.0});
  std::unique_ptr<DofMap> dofs;
  std::unique_ptr<AssemblerT10> assembler;
  SparseMatrix M, K, K_eff;
  Vector u, f, rhs;

  explicit Problem(int nx) {
    mesh = make_box_mesh({{0.0, 0.0, 0.0}, {1.0, 0.2, 0.2}, {nx, nx / 5, nx / 5}});
    dofs = std::make_unique<DofMap>(
        mesh, std::vector<DirichletCondition3>{{"x_min", {true, true, true}, {}, {}}});
    assembler = std::make_unique<AssemblerT10>(mesh, *material, *dofs);
    M = assembler->mass();
    K = K_eff = assembler->pattern();
    u = Vector::Zero(3 * static_cast<Eigen::Index>(mesh.num_nodes()));
    for (std::size_t k = 0; k < mesh.num_nodes(); ++k) {
      const double x = mesh.X[k].x(), z = mesh.X[k].z() - 0.1;
      u[3 * static_cast<Eigen::Index>(k)] = -2e-2 * x * z;
      u[3 * static_cast<Eigen::Index>(k) + 2] = 1e-2 * x * x;
    }
    assembler->assemble(u, f, &K);
    const double beta = 0.3025, dt = 1e-3;
    K_eff = K + (1.0 / (beta * dt * dt)) * M;
    rhs = dofs->restrict_to_free(f);
  }
};

Problem& problem(int nx) {
  static std::map<int, std::unique_ptr<Problem>> cache;
  auto& p = cache[nx];
  if (!p) p = std::make_unique<Problem>(nx);
  return *p;
}

void set_counters(benchmark::State& state, const Problem& p) {
  state.counters["elements"] = static_cast<double>(p.mesh.num_elements());
  state.counters["dofs"] = p.dofs->num_free();
  state.counters["threads"] = static_cast<double>(state.range(1));
  const double n = p.dofs->num_free();
  const double K_bytes = static_cast<double>(p.K_eff.nonZeros()) * (sizeof(double) + sizeof(int)) +
                         (n + 1.0) * sizeof(int);
  state.counters["K_bytes_per_dof"] = K_bytes / n;
}

/// The problem of state.range(0) cells along the beam (nx / 5 across: 15 -> 1,350, 35 -> 10,290,
/// 75 -> 101,250 elements), on state.range(1) threads.
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
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  state.counters["peak_rss_MB"] = static_cast<double>(usage.ru_maxrss) / 1024.0;
}

/// The solve with K_eff (dynamic: the mass term dominates the diagonal), or with the tangent
/// K_T alone (static: a Newton step of solve_static, where CG needs the most iterations).
void BM_Solve(benchmark::State& state, LinearSolverKind kind, bool dynamic) {
  Problem& p = setup(state);
  const SparseMatrix& K = dynamic ? p.K_eff : p.K;
  auto solver = make_linear_solver({kind, 1e-10, 0});
  solver->analyze(K);
  solver->factorize(K);
  for (auto _ : state) benchmark::DoNotOptimize(solver->solve(p.rhs));
  set_counters(state, p);
  state.counters["iterations"] = solver->iterations();
}

constexpr auto sizes = fsi::bench::sizes_on_1_and_2_threads<15, 35, 75>;

} // namespace

BENCHMARK(BM_Assembly)->Apply(sizes);
BENCHMARK_CAPTURE(BM_Factorize, cholmod, LinearSolverKind::cholmod)->Apply(sizes);
BENCHMARK_CAPTURE(BM_Solve, cholmod, LinearSolverKind::cholmod, true)->Apply(sizes);
BENCHMARK_CAPTURE(BM_Factorize, umfpack, LinearSolverKind::umfpack)->Apply(sizes);
BENCHMARK_CAPTURE(BM_Solve, umfpack, LinearSolverKind::umfpack, true)->Apply(sizes);
BENCHMARK_CAPTURE(BM_Factorize, cg_incomplete_cholesky, LinearSolverKind::cg_incomplete_cholesky)
    ->Apply(sizes);
BENCHMARK_CAPTURE(BM_Solve, cg_incomplete_cholesky, LinearSolverKind::cg_incomplete_cholesky, true)
    ->Apply(sizes);
BENCHMARK_CAPTURE(BM_Factorize, cg_jacobi, LinearSolverKind::cg_jacobi)->Apply(sizes);
BENCHMARK_CAPTURE(BM_Solve, cg_jacobi, LinearSolverKind::cg_jacobi, true)->Apply(sizes);
BENCHMARK_CAPTURE(BM_Solve, static_cg_incomplete_cholesky, LinearSolverKind::cg_incomplete_cholesky,
                  false)
    ->Apply(sizes);
BENCHMARK_CAPTURE(BM_Solve, static_cg_jacobi, LinearSolverKind::cg_jacobi, false)->Apply(sizes);

BENCHMARK_MAIN();
