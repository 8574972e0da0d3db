#pragma once
// Sparse linear solvers for the Newton systems K du = -R. The pattern is analysed once
// (analyze), the values refactorised every Newton iteration (factorize), and info() is checked
// after every call: a failure throws RunError, never returns a wrong answer.
#include <memory>
#include <string>

#include "structure_fem/near_null_space.hpp"
#include "structure_fem/types.hpp"

namespace fsi::fem {

enum class LinearSolverKind {
  cg_incomplete_cholesky, ///< conjugate gradient, IncompleteCholesky preconditioner (SPD K)
  cg_jacobi,              ///< conjugate gradient, diagonal preconditioner (SPD K)
  /// conjugate gradient, smoothed-aggregation multigrid V-cycle from the rigid-body modes
  /// (SPD K; structure_fem/smoothed_aggregation.hpp)
  cg_amg,
  cholmod,         ///< sparse direct supernodal Cholesky, CHOLMOD (SPD K)
  umfpack,         ///< sparse direct LU, UMFPACK (any nonsingular K, e.g. indefinite)
  simplicial_ldlt, ///< Eigen's sparse LDL^T (symmetric, no pivoting)
  /// The default: LDL^T, and UMFPACK LU for each factorisation LDL^T refuses (a K_eff that is
  /// not positive definite, e.g. a rubber beam at large deformation); counted in fallbacks().
  ldlt_or_lu,
};

struct LinearSolverOptions {
  /// The default: LDL^T, the fastest on 2D meshes of 48-20,000 T6 (docs/performance.md
  /// "structure_fem"), with LU where it fails.
  LinearSolverKind kind = LinearSolverKind::ldlt_or_lu;
  double cg_tolerance = 1e-12; ///< relative residual ||K x - b|| / ||b|| of CG, in (0, 1)
  int cg_max_iterations = 0;   ///< 0: Eigen's default (2 n); else >= 1
  /// cg_amg: multigrid levels are added until one has at most this many dofs (>= 1), which is
  /// then factorised.
  int amg_coarse_size = 2000;
  /// cg_amg: the hierarchy is kept across factorize() calls (only the finest level takes the
  /// new K) until a solve needs more than this many times the iterations of the first solve
  /// after the last build; the next factorize() then rebuilds it. 0: rebuilt at every
  /// factorize(); else >= 1.
  double amg_rebuild_ratio = 1.5;
};

/// Throws InputError naming the field, its value and the allowed range.
void validate(const LinearSolverOptions& options);
const char* to_string(LinearSolverKind kind);

class LinearSolver {
public:
  virtual ~LinearSolver() = default;
  /// Symbolic analysis of K's sparsity pattern (ordering); once per mesh.
  virtual void analyze(const SparseMatrix& K) = 0;
  /// The near null space of K (rigid-body modes on the free dofs, one block per node): used by
  /// cg_amg, which needs it before factorize; ignored by the other kinds.
  virtual void set_near_null_space(const NearNullSpace&) {}
  /// Numeric factorisation (direct) or preconditioner set-up (CG) for K's current values.
  virtual void factorize(const SparseMatrix& K) = 0;
  virtual Vector solve(const Vector& b) = 0;
  /// Iterations of the last solve (1 for direct solvers).
  virtual int iterations() const { return 1; }
  /// Factorisations done by the fallback LU since construction (ldlt_or_lu; else 0).
  virtual long fallbacks() const { return 0; }
  /// Preconditioner hierarchies built since construction (cg_amg; else 0): fewer than the
  /// factorize() calls when they are reused (LinearSolverOptions::amg_rebuild_ratio).
  virtual long setups() const { return 0; }
};

std::unique_ptr<LinearSolver> make_linear_solver(const LinearSolverOptions& options);

} // namespace fsi::fem
