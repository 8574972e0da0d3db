// Cost of one Newton iteration of the T6 solid, split into assembly (internal force + tangent),
// factorisation and solve (CHOLMOD; Eigen's SimplicialLDLT factorisation for comparison), or
// preconditioner set-up and CG solve (IncompleteCholesky), for about 200, 2k and 20k elements,
// on 1 and 2 threads (only the assembly loop is parallel).
#include "newton_problem.hpp"
#include "structure_fem/rectangle_mesher.hpp"

using namespace fsi::fem;
using fsi::Vec2;
using Problem = fsi::bench::NewtonProblem<T6>;

namespace {

/// A 1 x 0.25 beam clamped on the left, state.range(0) quads along it and a quarter of that
/// across (20 -> 200, 64 -> 2048, 200 -> 20000 elements), E = 1e6 Pa, rho = 1000 kg/m^3 (as in
/// the dam-break obstacle), plane strain, bent.
Problem& setup(benchmark::State& state) {
  return fsi::bench::newton_problem<Problem>(state, [](int ex) {
    return std::make_unique<Problem>(
        make_rectangle_mesh({{0.0, 0.0}, 1.0, 0.25, ex, ex / 4}),
        std::make_unique<StVenantKirchhoff>(
            MaterialOptions{1.0e6, 0.3, 1000.0, PlaneModel::plane_strain}),
        DirichletCondition{"left", true, true, {}},
        [](const Vec2& X) { return Vec2(-2e-2 * X.x() * (X.y() - 0.125), 1e-2 * X.x() * X.x()); });
  });
}

void BM_Assembly(benchmark::State& state) {
  fsi::bench::assembly(state, setup(state));
}

/// The factorisation of K_eff (CG: the preconditioner set-up).
void BM_Factorize(benchmark::State& state, LinearSolverKind kind) {
  fsi::bench::factorize(state, setup(state), kind);
}

void BM_Solve(benchmark::State& state, LinearSolverKind kind) {
  Problem& p = setup(state);
  fsi::bench::solve(state, p, p.K_eff, kind);
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
