// UMFPACK LU through its long-index routines (linear_solver.cpp, UmfPackLongLU): the values of
// each factorisation reach UMFPACK on the pattern analysed once, and a failure names UMFPACK's
// own status.
#include <catch2/catch.hpp>

#include "fsi/core/error.hpp"
#include "structure_fem/linear_solver.hpp"

using namespace fsi::fem;

namespace {

/// The tridiagonal 3 x 3 pattern with diagonal d and off-diagonals -1, compressed.
SparseMatrix tridiagonal(double d0, double d1, double d2) {
  SparseMatrix A(3, 3);
  A.insert(0, 0) = d0, A.insert(1, 0) = -1.0;
  A.insert(0, 1) = -1.0, A.insert(1, 1) = d1, A.insert(2, 1) = -1.0;
  A.insert(1, 2) = -1.0, A.insert(2, 2) = d2;
  A.makeCompressed();
  return A;
}

} // namespace

TEST_CASE("fem: UMFPACK refactorises each new K on the pattern analysed once",
          "[structure_fem][solver]") {
  const SparseMatrix A = tridiagonal(2.0, 2.0, 2.0), B = tridiagonal(2.0, -2.0, 2.0);
  const Vector ones = Vector::Ones(3);
  auto umfpack = make_linear_solver({LinearSolverKind::umfpack, 1e-12, 0});
  umfpack->analyze(A);
  umfpack->factorize(A);
  const Vector x = umfpack->solve(A * ones); // A (1, 1, 1) = (1, 0, 1)
  umfpack->factorize(B);                     // indefinite, the same pattern
  const Vector y = umfpack->solve(B * ones); // B (1, 1, 1) = (1, -4, 1)
  for (Eigen::Index i = 0; i < 3; ++i) {
    CHECK_THAT(x[i], Catch::Matchers::WithinAbs(1.0, 1e-15));
    CHECK_THAT(y[i], Catch::Matchers::WithinAbs(1.0, 1e-15));
  }
}

TEST_CASE("fem: a singular K stops UMFPACK with its own status", "[structure_fem][solver]") {
  const SparseMatrix S = tridiagonal(1.0, 2.0, 1.0); // S (1, 1, 1) = 0
  auto umfpack = make_linear_solver({LinearSolverKind::umfpack, 1e-12, 0});
  umfpack->analyze(S);
  CHECK_THROWS_WITH(umfpack->factorize(S),
                    "linear solver umfpack: factorisation failed: UMFPACK status 1: singular "
                    "matrix");
}
