#pragma once
// Smoothed-aggregation algebraic multigrid (Vanek, Mandel & Brezina 1996) as a preconditioner
// for CG on an SPD elasticity stiffness: aggregates of the node-block strength graph, the
// tentative prolongator from the rigid-body modes, smoothed by one damped Jacobi step, Galerkin
// coarse operators P^T A P, the coarsest level factorised (Eigen's SimplicialLDLT), and a V-cycle
// with one symmetric Gauss-Seidel sweep before and after the coarse correction, so that the
// preconditioner is symmetric positive definite.
#include <vector>

#include <Eigen/SparseCholesky>

#include "structure_fem/near_null_space.hpp"
#include "structure_fem/types.hpp"

namespace fsi::fem {

struct SmoothedAggregationOptions {
  double theta = 0.08;       ///< strength threshold on level 0, halved per level (Vanek, sec. 4.1)
  int coarse_size = 2000;    ///< levels are added until one has at most this many dofs
  int max_levels = 10;       ///< including the coarsest
  int power_iterations = 20; ///< for rho(D^-1 A) in the prolongator smoother's omega
};

class SmoothedAggregation {
public:
  explicit SmoothedAggregation(SmoothedAggregationOptions options = {}) : options_(options) {}
  /// Builds the hierarchy for A (SPD, both triangles stored) and its near null space. A is kept
  /// by reference: it must outlive every apply(). Throws RunError if a diagonal entry is not
  /// positive or the coarsest factorisation fails.
  void setup(const SparseMatrix& A, const NearNullSpace& near_null_space);
  /// Keeps the hierarchy built by setup() for an earlier A and puts a new A of the same size on
  /// the finest level (its smoother's diagonal recomputed): the V-cycle stays symmetric positive
  /// definite, a preconditioner lagged as in Newton-Krylov methods. With one level (the finest
  /// is the coarsest, factorised) it is setup() again. Throws RunError as setup().
  void refresh(const SparseMatrix& A, const NearNullSpace& near_null_space);
  /// z = M^-1 r: one V-cycle from z = 0. Allocates nothing.
  void apply(const Vector& r, Vector& z);
  /// Dofs of each level, finest first.
  std::vector<Eigen::Index> level_sizes() const;
  /// Operator complexity: nonzeros of all levels over the finest's.
  double operator_complexity() const;

private:
  struct Level {
    SparseMatrix A;    ///< Galerkin operator (empty on level 0: the caller's A)
    SparseMatrix P, R; ///< prolongator to this level from the next coarser, R = P^T
    Vector inv_diagonal;
    Vector x, b, r; ///< V-cycle work
  };
  const SparseMatrix& op(std::size_t l) const { return l == 0 ? *A0_ : levels_[l].A; }
  void cycle(std::size_t l);

  SmoothedAggregationOptions options_;
  const SparseMatrix* A0_ = nullptr;
  std::vector<Level> levels_;
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower> coarsest_;
};

} // namespace fsi::fem
