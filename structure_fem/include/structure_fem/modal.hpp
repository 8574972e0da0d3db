#pragma once
// The lowest natural modes of K phi = omega^2 M phi (K, M symmetric positive definite on the free
// dofs) by subspace iteration (Bathe, Finite Element Procedures, 2nd ed., sec. 11.6): the block
// X_{k+1} = K^{-1} M X_k, M-orthonormalised by a Rayleigh–Ritz step on the projected pair.
#include "structure_fem/types.hpp"

namespace fsi::fem {

struct Modes {
  Vector omega_squared;  ///< ascending [rad^2/s^2]
  Eigen::MatrixXd shape; ///< column i: the M-orthonormal mode of omega_squared[i]
};

/// The `count` lowest modes, iterated on a block of min(2 count, count + 8) vectors until every
/// wanted omega^2 changes by less than `tolerance` (relative) between iterations. K is factorised
/// once by CHOLMOD. Throws RunError if the factorisation fails or after `max_iterations`.
Modes lowest_modes(const SparseMatrix& K, const SparseMatrix& M, int count,
                   double tolerance = 1e-10, int max_iterations = 200);

} // namespace fsi::fem
