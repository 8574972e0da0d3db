#include "structure_fem/linear_solver.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <sstream>

#include <Eigen/CholmodSupport>
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>
#include <Eigen/UmfPackSupport>

#include "cg_amg.hpp"
#include "fsi/core/error.hpp"

namespace fsi::fem {

namespace {

// Eigen's ComputationInfo in its order: Success, NumericalIssue, NoConvergence, InvalidInput.
const char* info_text(Eigen::ComputationInfo info) {
  static constexpr std::array<const char*, 4> text = {
      "success", "numerical issue (matrix not positive definite or singular)", "no convergence",
      "invalid input"};
  const auto i = static_cast<std::size_t>(info);
  return i < text.size() ? text[i] : "unknown";
}

void check(Eigen::ComputationInfo info, LinearSolverKind kind, const char* phase,
           const std::string& status = {}) {
  if (info != Eigen::Success)
    throw RunError(std::string("linear solver ") + to_string(kind) + ": " + phase +
                   " failed: " + (status.empty() ? std::string(info_text(info)) : status));
}

/// The library's own status of the last factorisation where Eigen keeps it (empty if none): Eigen's
/// NumericalIssue does not tell a singular matrix from a factor out of memory.
template <class Solver> std::string library_status(Solver& s) {
  int code = 0;
  const char* what = "";
  const char* library = "";
  if constexpr (requires { s.umfpackFactorizeReturncode(); }) {
    library = "UMFPACK";
    code = s.umfpackFactorizeReturncode();
    if (code == UMFPACK_WARNING_singular_matrix) what = ": singular matrix";
    if (code == UMFPACK_ERROR_out_of_memory) what = ": out of memory";
  } else if constexpr (requires { s.cholmod(); }) {
    library = "CHOLMOD";
    code = s.cholmod().status;
    if (code == CHOLMOD_NOT_POSDEF) what = ": not positive definite";
    if (code == CHOLMOD_OUT_OF_MEMORY) what = ": out of memory";
    if (code == CHOLMOD_TOO_LARGE) what = ": problem too large";
  }
  if (*library == '\0' || code == 0) return {};
  return std::string(library) + " status " + std::to_string(code) + what;
}

/// UMFPACK's LU through its long-index routines (umfpack_dl_*): Eigen's UmfPackLU on a copy of K
/// with SuiteSparse_long indices. On K's int indices it calls umfpack_di_*, which address their
/// workspace by int: out of memory at 101,250 T10 (docs/structure_fem.md, "Benchmarks"). The
/// pattern is copied at analysis, K's values into the copy's own array at each factorisation.
class UmfPackLongLU {
public:
  using LongMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, SuiteSparse_long>;
  void analyzePattern(const SparseMatrix& K) {
    K_ = K;
    lu_.analyzePattern(K_);
  }
  /// K: compressed, with the pattern of the last analyzePattern.
  void factorize(const SparseMatrix& K) {
    assert(K.isCompressed() && K.nonZeros() == K_.nonZeros());
    std::copy_n(K.valuePtr(), K.nonZeros(), K_.valuePtr());
    lu_.factorize(K_);
  }
  Eigen::ComputationInfo info() const { return lu_.info(); }
  int umfpackFactorizeReturncode() const { return lu_.umfpackFactorizeReturncode(); }
  Vector solve(const Vector& b) const { return lu_.solve(b); }

private:
  LongMatrix K_; // the UMFPACK solve refines against it: it lives as long as the factors
  Eigen::UmfPackLU<LongMatrix> lu_;
};

/// An Eigen sparse solver (analyzePattern / factorize / solve) behind LinearSolver: the pattern
/// analysis and the factorisation, checked; `factorize_phase` names the latter in messages.
template <class Solver> class EigenSolver : public LinearSolver {
public:
  void analyze(const SparseMatrix& K) override {
    solver_.analyzePattern(K);
    check(solver_.info(), kind_, "pattern analysis");
  }
  void factorize(const SparseMatrix& K) override {
    solver_.factorize(K);
    check(solver_.info(), kind_, factorize_phase_, library_status(solver_));
  }

protected:
  EigenSolver(LinearSolverKind kind, const char* factorize_phase)
      : kind_(kind), factorize_phase_(factorize_phase) {}
  LinearSolverKind kind_;
  const char* factorize_phase_;
  Solver solver_;
};

/// Any Eigen sparse direct solver.
template <class Solver> class DirectSolver final : public EigenSolver<Solver> {
public:
  explicit DirectSolver(LinearSolverKind kind) : EigenSolver<Solver>(kind, "factorisation") {
    if constexpr (requires(Solver & s) { s.cholmod(); })
      this->solver_.cholmod().print = 0; // no stderr
  }
  void factorize(const SparseMatrix& K) override {
    EigenSolver<Solver>::factorize(K);
    // LDL^T without pivoting factorises an indefinite K too: a pivot D_kk <= 0 says K is not
    // positive definite, as CHOLMOD's LL^T reports it (Newton's K_eff must be).
    if constexpr (requires(Solver & s) { s.vectorD(); }) {
      Eigen::Index k = 0;
      if (this->solver_.vectorD().size() > 0 && !(this->solver_.vectorD().minCoeff(&k) > 0.0)) {
        std::ostringstream s;
        s << "linear solver " << to_string(this->kind_)
          << ": factorisation failed: matrix not positive definite (pivot " << k << " of "
          << this->solver_.vectorD().size() << " is " << this->solver_.vectorD()[k] << ")";
        throw RunError(s.str());
      }
    }
  }
  Vector solve(const Vector& b) override {
    Vector x = this->solver_.solve(b);
    check(this->solver_.info(), this->kind_, "solve");
    if (!x.allFinite())
      throw RunError(std::string("linear solver ") + to_string(this->kind_) +
                     ": non-finite solution");
    return x;
  }
};

/// ldlt_or_lu: LDL^T first for every factorisation, UMFPACK LU when LDL^T refuses K. Deciding
/// per factorisation keeps the result independent of history (a restart is bitwise the run).
class LdltOrLu final : public LinearSolver {
public:
  void analyze(const SparseMatrix& K) override {
    ldlt_.analyze(K);
    lu_analyzed_ = false;
  }
  void factorize(const SparseMatrix& K) override {
    try {
      ldlt_.factorize(K);
      active_ = &ldlt_;
    } catch (const RunError&) {
      if (!lu_analyzed_) lu_.analyze(K), lu_analyzed_ = true;
      lu_.factorize(K);
      active_ = &lu_;
      ++fallbacks_;
    }
  }
  Vector solve(const Vector& b) override { return active_->solve(b); }
  long fallbacks() const override { return fallbacks_; }

private:
  DirectSolver<Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower>> ldlt_{
      LinearSolverKind::simplicial_ldlt};
  DirectSolver<UmfPackLongLU> lu_{LinearSolverKind::umfpack};
  LinearSolver* active_ = &ldlt_;
  bool lu_analyzed_ = false;
  long fallbacks_ = 0;
};

template <class Preconditioner>
using Cg = Eigen::ConjugateGradient<SparseMatrix, Eigen::Lower | Eigen::Upper, Preconditioner>;

template <class Preconditioner> class CgSolver final : public EigenSolver<Cg<Preconditioner>> {
public:
  CgSolver(LinearSolverKind kind, const LinearSolverOptions& o)
      : EigenSolver<Cg<Preconditioner>>(kind, "preconditioner set-up") {
    this->solver_.setTolerance(o.cg_tolerance);
    if (o.cg_max_iterations > 0) this->solver_.setMaxIterations(o.cg_max_iterations);
  }
  Vector solve(const Vector& b) override {
    Vector x = this->solver_.solve(b);
    if (this->solver_.info() != Eigen::Success) {
      std::ostringstream s;
      s << "linear solver " << to_string(this->kind_) << ": no convergence after "
        << this->solver_.iterations() << " iterations (relative residual " << this->solver_.error()
        << ", tolerance " << this->solver_.tolerance() << ")";
      throw RunError(s.str());
    }
    return x;
  }
  int iterations() const override { return static_cast<int>(this->solver_.iterations()); }
};

} // namespace

const char* to_string(LinearSolverKind kind) {
  switch (kind) {
  case LinearSolverKind::cg_incomplete_cholesky:
    return "cg_incomplete_cholesky";
  case LinearSolverKind::cg_jacobi:
    return "cg_jacobi";
  case LinearSolverKind::cg_amg:
    return "cg_amg";
  case LinearSolverKind::cholmod:
    return "cholmod";
  case LinearSolverKind::umfpack:
    return "umfpack";
  case LinearSolverKind::simplicial_ldlt:
    return "simplicial_ldlt";
  case LinearSolverKind::ldlt_or_lu:
    return "ldlt_or_lu";
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
  if (o.amg_coarse_size < 1)
    throw InputError("linear_solver: amg_coarse_size = " + std::to_string(o.amg_coarse_size) +
                     ": must be >= 1");
  if (!(o.amg_rebuild_ratio == 0.0 || o.amg_rebuild_ratio >= 1.0))
    throw InputError("linear_solver: amg_rebuild_ratio = " + std::to_string(o.amg_rebuild_ratio) +
                     ": must be 0 (rebuild at every factorisation) or >= 1");
}

std::unique_ptr<LinearSolver> make_linear_solver(const LinearSolverOptions& o) {
  validate(o);
  using K = LinearSolverKind;
  switch (o.kind) {
  case K::cg_incomplete_cholesky:
    return std::make_unique<CgSolver<Eigen::IncompleteCholesky<double>>>(o.kind, o);
  case K::cg_jacobi:
    return std::make_unique<CgSolver<Eigen::DiagonalPreconditioner<double>>>(o.kind, o);
  case K::cg_amg:
    return make_cg_amg(o);
  case K::cholmod:
    return std::make_unique<DirectSolver<Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower>>>(
        o.kind);
  case K::umfpack:
    return std::make_unique<DirectSolver<UmfPackLongLU>>(o.kind);
  case K::simplicial_ldlt:
    return std::make_unique<DirectSolver<Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower>>>(
        o.kind);
  case K::ldlt_or_lu:
    return std::make_unique<LdltOrLu>();
  }
  throw InputError("linear_solver: unknown kind");
}

} // namespace fsi::fem
