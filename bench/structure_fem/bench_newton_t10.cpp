// Cost of one Newton iteration of the T10 solid (issue 44), split as bench_newton.cpp splits the
// T6 one: assembly (internal force + tangent), factorisation and solve (CHOLMOD, the 3-D default;
// UMFPACK), or preconditioner set-up and CG solve (incomplete Cholesky, Jacobi), for about 1k,
// 10k and 100k elements on 1 and 2 threads (only the assembly loop is parallel). Counters: the
// free DOFs, CG iterations, the bytes per free DOF of K_eff (values and indices), and the
// process's peak resident set after the factorisation (run one solver and size per process for
// that figure to be the factor's).
#include <sys/resource.h>

#include "newton_problem.hpp"
#include "structure_fem/box_mesher.hpp"
#include "structure_fem/loads.hpp"
#include "structure_fem/structure.hpp"

using namespace fsi::fem;
using fsi::Vec3;
using Problem = fsi::bench::NewtonProblem<T10>;

namespace {

/// A 1 x 0.2 x 0.2 beam clamped at x = 0, cubic cells of side 1 / nx split into 6 T10 each
/// (nx / 5 across: 15 -> 1,350, 35 -> 10,290, 75 -> 101,250 elements), E = 1e6 Pa, nu = 0.3,
/// rho = 1000 kg/m^3 (as bench_newton.cpp's T6 beam), bent in the x-z plane.
Problem& setup(benchmark::State& state) {
  return fsi::bench::newton_problem<Problem>(state, [](int nx) {
    return std::make_unique<Problem>(
        make_box_mesh({{0.0, 0.0, 0.0}, {1.0, 0.2, 0.2}, {nx, nx / 5, nx / 5}}),
        make_material_3d({1.0e6, 0.3, 1000.0}),
        DirichletCondition3{"x_min", {true, true, true}, {}, {}}, [](const Vec3& X) {
          return Vec3(-2e-2 * X.x() * (X.z() - 0.1), 0.0, 1e-2 * X.x() * X.x());
        });
  });
}

void BM_Assembly(benchmark::State& state) {
  fsi::bench::assembly(state, setup(state));
}

/// The factorisation, and the process's peak resident set after it (run one solver and size
/// per process for that to be the factor's).
void BM_Factorize(benchmark::State& state, LinearSolverKind kind) {
  fsi::bench::factorize(state, setup(state), kind);
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  state.counters["peak_rss_MB"] = static_cast<double>(usage.ru_maxrss) / 1024.0;
}

/// The solve with K_eff (dynamic: the mass term dominates the diagonal), or with the tangent
/// K_T alone (static: a Newton step of solve_static, where CG needs the most iterations).
void BM_Solve(benchmark::State& state, LinearSolverKind kind, bool dynamic) {
  Problem& p = setup(state);
  fsi::bench::solve(state, p, dynamic ? p.K_eff : p.K, kind);
}

/// factorize + solve of a static Newton iteration (K_T) with cg_amg's hierarchy rebuilt or kept.
void BM_AmgIteration(benchmark::State& state, double rebuild_ratio) {
  Problem& p = setup(state);
  fsi::bench::amg_iteration(state, p, p.K, rebuild_ratio);
}

/// A whole static solve at large deflection with cg_amg, its hierarchy rebuilt at every Newton
/// iteration or kept while CG's iterations stay within 1.5x: the benchmark's beam (nx cells
/// along) under an end shear of P L^2 / (E I) = 1.8 (a tip rotation near 40 degrees, as the
/// CalculiX NLGEOM test) in 5 load steps. Counters: Newton iterations, CG iterations, set-ups.
void BM_StaticSolve(benchmark::State& state, double rebuild_ratio) {
  const int nx = static_cast<int>(state.range(0));
  const TetMesh mesh = make_box_mesh({{0.0, 0.0, 0.0}, {1.0, 0.2, 0.2}, {nx, nx / 5, nx / 5}});
  const double traction = 1.8 * 1.0e6 * std::pow(0.2, 4) / 12.0 / (0.2 * 0.2); // P / area
  const Vector f =
      face_traction_forces(mesh, "x_max", [&](const Vec3&) { return Vec3(0.0, 0.0, -traction); });
  StructureT10Options o;
  o.material = {1.0e6, 0.3, 1000.0};
  o.clamped = {{"x_min", {true, true, true}, {}, {}}};
  o.linear_solver = {LinearSolverKind::cg_amg, 1e-10, 0};
  o.linear_solver.amg_rebuild_ratio = rebuild_ratio;
  long newton = 0, cg = 0, setups = 0;
  for (auto _ : state) {
    StructureT10 s(mesh, o);
    s.set_external_forces(f);
    for (const auto& r : s.solve_static({5})) {
      newton += r.iterations;
      for (const auto& it : r.history) cg += it.linear_iterations;
    }
    setups += s.linear_solver_setups();
    benchmark::DoNotOptimize(s.displacement().data());
  }
  const auto runs = static_cast<double>(state.iterations());
  state.counters["elements"] = static_cast<double>(mesh.num_elements());
  state.counters["newton_iterations"] = static_cast<double>(newton) / runs;
  state.counters["cg_iterations"] = static_cast<double>(cg) / runs;
  state.counters["setups"] = static_cast<double>(setups) / runs;
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
BENCHMARK_CAPTURE(BM_Factorize, cg_amg, LinearSolverKind::cg_amg)->Apply(sizes);
BENCHMARK_CAPTURE(BM_Solve, cg_amg, LinearSolverKind::cg_amg, true)->Apply(sizes);
BENCHMARK_CAPTURE(BM_Solve, static_cg_amg, LinearSolverKind::cg_amg, false)->Apply(sizes);

BENCHMARK_CAPTURE(BM_AmgIteration, rebuilt, 0.0)->Apply(sizes);
BENCHMARK_CAPTURE(BM_AmgIteration, kept, 1.5)->Apply(sizes);
BENCHMARK_CAPTURE(BM_StaticSolve, cg_amg_rebuilt, 0.0)->Arg(15)->Arg(25)->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(BM_StaticSolve, cg_amg_kept, 1.5)->Arg(15)->Arg(25)->Unit(benchmark::kSecond);

BENCHMARK_MAIN();
