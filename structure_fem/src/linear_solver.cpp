#include "structure_fem/linear_solver.hpp"

#include <sstream>

#include <Eigen/CholmodSupport>
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>
#include <Eigen/UmfPackSupport>

#include "fsi/core/error.hpp"

namespace fsi::fem {

namespace {

const char* info_text(Eigen::ComputationInfo info) {
  switch (info) {
  case Eigen::Success:
    return "success";
  case Eigen::NumericalIssue:
    return "numerical issue (matrix not positive definite or singular)";
  case Eigen::NoConvergence:
    return "no convergence";
  case Eigen::InvalidInput:
    return "invalid input";
  }
  return "unknown";
}

void check(Eigen::ComputationInfo info, LinearSolverKind kind, const char* phase) {
  if (info != Eigen::Success)
    throw RunError(std::string("linear solver ") + to_string(kind) + ": " + phase +
                   " failed: " + info_text(info));
}

/// Any Eigen sparse direct solver with analyzePattern / factorize / solve.
template <class Solver> class DirectSolver final : public LinearSolver {
public:
  explicit DirectSolver(LinearSolverKind kind) : kind_(kind) {
    if constexpr (requires(Solver & s) { s.cholmod(); }) solver_.cholmod().print = 0; // no stderr
  }
  void analyze(const SparseMatrix& K) override {
    solver_.analyzePattern(K);
    check(solver_.info(), kind_, "pattern analysis");
  }
  void factorize(const SparseMatrix& K) override {
    solver_.factorize(K);
    check(solver_.info(), kind_, "factorisation");
  }
  Vector solve(const Vector& b) override {
    Vector x = solver_.solve(b);
    check(solver_.info(), kind_, "solve");
    if (!x.allFinite())
      throw RunError(std::string("linear solver ") + to_string(kind_) + ": non-finite solution");
    return x;
  }

private:
  LinearSolverKind kind_;
  Solver solver_;
};

template <class Preconditioner> class CgSolver final : public LinearSolver {
public:
  CgSolver(LinearSolverKind kind, const LinearSolverOptions& o) : kind_(kind) {
    solver_.setTolerance(o.cg_tolerance);
    if (o.cg_max_iterations > 0) solver_.setMaxIterations(o.cg_max_iterations);
  }
  void analyze(const SparseMatrix& K) override {
    solver_.analyzePattern(K);
    check(solver_.info(), kind_, "pattern analysis");
  }
  void factorize(const SparseMatrix& K) override {
    solver_.factorize(K);
    check(solver_.info(), kind_, "preconditioner set-up");
  }
  Vector solve(const Vector& b) override {
    Vector x = solver_.solve(b);
    if (solver_.info() != Eigen::Success) {
      std::ostringstream s;
      s << "linear solver " << to_string(kind_) << ": no convergence after " << solver_.iterations()
        << " iterations (relative residual " << solver_.error() << ", tolerance "
        << solver_.tolerance() << ")";
      throw RunError(s.str());
    }
    return x;
  }
  int iterations() const override { return static_cast<int>(solver_.iterations()); }

private:
  LinearSolverKind kind_;
  Eigen::ConjugateGradient<SparseMatrix, Eigen::Lower | Eigen::Upper, Preconditioner> solver_;
};

} // namespace

const char* to_string(LinearSolverKind kind) {
  switch (kind) {
  case LinearSolverKind::cg_incomplete_cholesky:
    return "cg_incomplete_cholesky";
  case LinearSolverKind::cg_jacobi:
    return "cg_jacobi";
  case LinearSolverKind::cholmod:
    return "cholmod";
  case LinearSolverKind::umfpack:
    return "umfpack";
  case LinearSolverKind::simplicial_ldlt:
    return "simplicial_ldlt";
  }
  return "unknown";
}

void validate(const LinearSolverOptions& o) {
  if (!(o.cg_tolerance > 0.0 && o.cg_tolerance < 1.0))
    throw InputError("linear_solver: cg_tolerance = " + std::to_string(o.cg_tolerance) +
                     ": must be in (0, 1)");
  if (o.cg_max_iterations < 0)
    throw InputError("linear_solver: cg_max_iterations = " + std::to_string(o.cg_max_iterations) +
                     ": must be >= 0 (0: default)");
}

std::unique_ptr<LinearSolver> make_linear_solver(const LinearSolverOptions& o) {
  validate(o);
  using K = LinearSolverKind;
  switch (o.kind) {
  case K::cg_incomplete_cholesky:
    return std::make_unique<CgSolver<Eigen::IncompleteCholesky<double>>>(o.kind, o);
  case K::cg_jacobi:
    return std::make_unique<CgSolver<Eigen::DiagonalPreconditioner<double>>>(o.kind, o);
  case K::cholmod:
    return std::make_unique<DirectSolver<Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower>>>(
        o.kind);
  case K::umfpack:
    return std::make_unique<DirectSolver<Eigen::UmfPackLU<SparseMatrix>>>(o.kind);
  case K::simplicial_ldlt:
    return std::make_unique<DirectSolver<Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower>>>(
        o.kind);
  }
  throw InputError("linear_solver: unknown kind");
}

} // namespace fsi::fem
