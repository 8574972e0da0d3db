#include "structure_fem/modal.hpp"

#include <algorithm>
#include <string>

#include <Eigen/Eigenvalues>

#include "fsi/core/error.hpp"
#include "structure_fem/linear_solver.hpp"

namespace fsi::fem {

Modes lowest_modes(const SparseMatrix& K, const SparseMatrix& M, int count, double tolerance,
                   int max_iterations) {
  const Eigen::Index n = K.rows(), q = std::min<Eigen::Index>(std::min(2 * count, count + 8), n);
  const auto solver = make_linear_solver({LinearSolverKind::cholmod});
  solver->analyze(K);
  solver->factorize(K);
  // Starting block (Bathe 11.6.2): the diagonal of M, then unit vectors at the dofs of largest
  // m_ii / k_ii, which excite the low modes.
  Eigen::MatrixXd X = Eigen::MatrixXd::Zero(n, q);
  X.col(0) = M.diagonal();
  std::vector<Eigen::Index> order(static_cast<std::size_t>(n));
  for (Eigen::Index i = 0; i < n; ++i) order[static_cast<std::size_t>(i)] = i;
  const Vector ratio = M.diagonal().cwiseQuotient(K.diagonal());
  std::sort(order.begin(), order.end(), [&](auto a, auto b) { return ratio[a] > ratio[b]; });
  for (Eigen::Index j = 1; j < q; ++j) X(order[static_cast<std::size_t>(j - 1)], j) = 1.0;
  Vector previous = Vector::Constant(count, -1.0);
  for (int k = 0; k < max_iterations; ++k) {
    Eigen::MatrixXd Y(n, q);
    const Eigen::MatrixXd MX = M * X;
    for (Eigen::Index j = 0; j < q; ++j) Y.col(j) = solver->solve(MX.col(j)); // K Y = M X
    // Rayleigh–Ritz on span(Y): K_r z = omega^2 M_r z, X = Y z (M-orthonormal, ascending).
    const Eigen::MatrixXd K_r = Y.transpose() * (K * Y), M_r = Y.transpose() * (M * Y);
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> ritz(K_r, M_r);
    if (ritz.info() != Eigen::Success) throw RunError("modes: the Ritz eigenproblem failed");
    X = Y * ritz.eigenvectors();
    const Vector omega2 = ritz.eigenvalues().head(count);
    if (((omega2 - previous).cwiseAbs().array() <= tolerance * omega2.array()).all())
      return {omega2, X.leftCols(count)};
    previous = omega2;
  }
  throw RunError("modes: subspace iteration did not converge in " + std::to_string(max_iterations) +
                 " iterations");
}

} // namespace fsi::fem
