#pragma once
// What the T6 and T10 Newton benchmarks share: a clamped beam in a bent state and the effective
// tangent K_eff = K_T + M / (beta dt^2) of a Newmark step (beta = 0.3025, dt = 1e-3 s), one
// instance per size, and the bodies of the assembly, factorisation and solve benchmarks.
#include <benchmark/benchmark.h>

#include <functional>
#include <map>
#include <memory>

#include "common/sweep.hpp"
#include "structure_fem/assembly.hpp"
#include "structure_fem/linear_solver.hpp"

namespace fsi::bench {

template <class Family> struct NewtonProblem {
  using Mesh = typename Family::Mesh;
  using Point = Eigen::Matrix<double, Family::dim, 1>;

  Mesh mesh;
  std::unique_ptr<typename Family::Material> material;
  std::unique_ptr<fem::DofMap> dofs;
  std::unique_ptr<fem::BasicAssembler<Family>> assembler;
  fem::SparseMatrix M, K, K_eff;
  fem::Vector u, f, rhs;

  /// `clamp` fixes the beam's root; `bent(X)` is the displacement of the state assembled at.
  NewtonProblem(Mesh m, std::unique_ptr<typename Family::Material> law,
                const typename Family::Condition& clamp,
                const std::function<Point(const Point&)>& bent)
      : mesh(std::move(m)), material(std::move(law)) {
    dofs = std::make_unique<fem::DofMap>(mesh, std::vector<typename Family::Condition>{clamp});
    assembler = std::make_unique<fem::BasicAssembler<Family>>(mesh, *material, *dofs);
    M = assembler->mass();
    K = K_eff = assembler->pattern();
    constexpr int D = Family::dim;
    u = fem::Vector::Zero(D * static_cast<Eigen::Index>(mesh.num_nodes()));
    for (std::size_t k = 0; k < mesh.num_nodes(); ++k)
      u.template segment<D>(D * static_cast<Eigen::Index>(k)) = bent(mesh.X[k]);
    assembler->assemble(u, f, &K);
    const double beta = 0.3025, dt = 1e-3;
    K_eff = K + (1.0 / (beta * dt * dt)) * M;
    rhs = dofs->restrict_to_free(f);
  }
};

/// The problem of size n made by `make` once, on state.range(1) threads.
template <class P>
P& newton_problem(benchmark::State& state, const std::function<std::unique_ptr<P>(int)>& make) {
  static std::map<int, std::unique_ptr<P>> cache;
  auto& p = cache[static_cast<int>(state.range(0))];
  if (!p) p = make(static_cast<int>(state.range(0)));
  use_threads(state, 1);
  return *p;
}

/// Elements, free DOFs, threads, and K_eff's bytes per free DOF (values and indices).
template <class P> void set_counters(benchmark::State& state, const P& p) {
  const double n = p.dofs->num_free();
  state.counters["elements"] = static_cast<double>(p.mesh.num_elements());
  state.counters["dofs"] = n;
  state.counters["threads"] = static_cast<double>(state.range(1));
  state.counters["K_bytes_per_dof"] =
      (static_cast<double>(p.K_eff.nonZeros()) * (sizeof(double) + sizeof(int)) +
       (n + 1.0) * sizeof(int)) /
      n;
}

template <class P> void assembly(benchmark::State& state, P& p) {
  fem::Vector f;
  for (auto _ : state) {
    p.assembler->assemble(p.u, f, &p.K);
    benchmark::DoNotOptimize(p.K.valuePtr());
  }
  set_counters(state, p);
}

/// The factorisation of K_eff (CG: the preconditioner set-up).
template <class P> void factorize(benchmark::State& state, P& p, fem::LinearSolverKind kind) {
  auto solver = fem::make_linear_solver({kind, 1e-10, 0});
  solver->set_near_null_space(
      fem::rigid_body_modes<P::Point::RowsAtCompileTime>(*p.dofs, p.mesh.X));
  solver->analyze(p.K_eff);
  for (auto _ : state) solver->factorize(p.K_eff);
  set_counters(state, p);
}

/// The solve with K (K_eff, or the tangent alone), factorised once.
template <class P>
void solve(benchmark::State& state, P& p, const fem::SparseMatrix& K, fem::LinearSolverKind kind) {
  auto solver = fem::make_linear_solver({kind, 1e-10, 0});
  solver->set_near_null_space(
      fem::rigid_body_modes<P::Point::RowsAtCompileTime>(*p.dofs, p.mesh.X));
  solver->analyze(K);
  solver->factorize(K);
  for (auto _ : state) benchmark::DoNotOptimize(solver->solve(p.rhs));
  set_counters(state, p);
  state.counters["iterations"] = solver->iterations();
}

/// One Newton iteration's linear work with cg_amg, factorize(K) and a solve, after a first one
/// outside the timing: the hierarchy rebuilt every time (rebuild_ratio 0) or kept
/// (LinearSolverOptions::amg_rebuild_ratio; the same K, so it is never judged stale).
template <class P>
void amg_iteration(benchmark::State& state, P& p, const fem::SparseMatrix& K,
                   double rebuild_ratio) {
  fem::LinearSolverOptions o{fem::LinearSolverKind::cg_amg, 1e-10, 0};
  o.amg_rebuild_ratio = rebuild_ratio;
  auto solver = fem::make_linear_solver(o);
  solver->set_near_null_space(
      fem::rigid_body_modes<P::Point::RowsAtCompileTime>(*p.dofs, p.mesh.X));
  solver->analyze(K);
  solver->factorize(K);
  solver->solve(p.rhs);
  const long setups = solver->setups();
  for (auto _ : state) {
    solver->factorize(K);
    benchmark::DoNotOptimize(solver->solve(p.rhs));
  }
  set_counters(state, p);
  state.counters["iterations"] = solver->iterations();
  state.counters["setups_per_iteration"] =
      static_cast<double>(solver->setups() - setups) / static_cast<double>(state.iterations());
}

} // namespace fsi::bench
