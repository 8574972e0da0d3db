// Small-load cantilever: beam theory, mesh convergence, linear solvers.
#include <catch2/catch.hpp>

#include <cmath>

#include "cantilever.hpp"
#include "fsi/core/error.hpp"

using namespace fem_test;

TEST_CASE("fem: cantilever tip deflection matches Timoshenko beam theory",
          "[structure_fem][cantilever]") {
  const Beam b;           // L = 1, h = 0.1, plane strain, nu = 0.3, 40 x 4 quads
  const double P = 1.0e4; // deflection ~ 2e-4 L: linear regime
  const double fem = static_tip_deflection(b, P);
  const double beam = timoshenko_tip_deflection(b, P);
  WARN("tip deflection: FEM " << fem << ", Timoshenko " << beam << ", relative difference "
                              << (fem - beam) / beam);
  CHECK_THAT(fem, Catch::Matchers::WithinRel(beam, 0.01));
}

TEST_CASE("fem: cantilever tip error converges at the rate of quadratic elements",
          "[structure_fem][convergence]") {
  // A full clamp has corner singularities that cap any element's rate on uniform meshes (see
  // docs/structure_fem.md). Here the root is a symmetry plane (roller u_x = 0, u_y = 0 at its
  // mid node) carrying the parabolic shear reaction as a traction, so the solution is smooth and
  // the point constraint carries no force.
  const double P = 1.0e4;
  auto tip = [&](int n) {
    Beam b;
    b.ex = 5 * n, b.ey = n;
    const Mesh mesh = beam_mesh(b);
    auto o = beam_options(b);
    o.clamped = {{"left", true, false, {}}, {"", false, true, {node_at(mesh, {0.0, 0.5 * b.h})}}};
    Structure s(mesh, o);
    auto shear = [&](double y) { return P * 6.0 * y * (b.h - y) / (b.h * b.h * b.h); };
    const Vector f =
        edge_traction_field_forces(
            s.mesh(), "left", [&](const fsi::Vec2& X) { return fsi::Vec2(0.0, shear(X.y())); }) +
        edge_traction_field_forces(
            s.mesh(), "right", [&](const fsi::Vec2& X) { return fsi::Vec2(0.0, -shear(X.y())); });
    s.set_external_forces(f);
    s.solve_static();
    return -s.displacement()[2 * tip_node(s.mesh(), b) + 1];
  };
  const double reference = tip(16); // 80 x 16 quads
  const double e1 = std::abs(tip(1) - reference), e2 = std::abs(tip(2) - reference),
               e4 = std::abs(tip(4) - reference);
  const double p1 = std::log2(e1 / e2), p2 = std::log2(e2 / e4);
  WARN("tip " << reference << "; errors " << e1 << ", " << e2 << ", " << e4 << "; observed orders "
              << p1 << ", " << p2);
  // Quadratic elements: displacement error O(h^3) (L2), up to O(h^4) for a load functional.
  CHECK(p1 > 3.0);
  CHECK(p2 > 3.0);
}

TEST_CASE("fem: linear solvers give the same solution", "[structure_fem][solver]") {
  Beam b;
  b.ex = 20, b.ey = 4;
  auto solve = [&](LinearSolverKind kind) {
    auto o = beam_options(b);
    o.linear_solver.kind = kind;
    o.linear_solver.cg_tolerance = 1e-13;
    o.newton.residual_rtol = 1e-10;
    o.newton.increment_rtol = 1e-10;
    o.gravity = {0.0, -9.81};
    Structure s(beam_mesh(b), o);
    s.set_external_forces(tip_load(s.mesh(), b, 1.0e6));
    s.solve_static();
    return Vector(s.displacement());
  };
  const Vector u_cholmod = solve(LinearSolverKind::cholmod);
  for (auto kind : {LinearSolverKind::cg_incomplete_cholesky, LinearSolverKind::cg_jacobi,
                    LinearSolverKind::umfpack, LinearSolverKind::simplicial_ldlt}) {
    const Vector u = solve(kind);
    INFO(to_string(kind));
    CHECK((u - u_cholmod).norm() / u_cholmod.norm() < 1e-8);
  }
}

TEST_CASE("fem: CHOLMOD and LDLT refuse an indefinite matrix", "[structure_fem][solver]") {
  SparseMatrix A(3, 3);
  A.insert(0, 0) = 1.0;
  A.insert(1, 1) = -2.0;
  A.insert(2, 2) = 1.0;
  A.makeCompressed();
  auto cholmod = make_linear_solver({LinearSolverKind::cholmod, 1e-12, 0});
  cholmod->analyze(A);
  CHECK_THROWS_AS(cholmod->factorize(A), fsi::RunError);
  auto ldlt = make_linear_solver({LinearSolverKind::simplicial_ldlt, 1e-12, 0});
  ldlt->analyze(A);
  CHECK_THROWS_WITH(ldlt->factorize(A),
                    Catch::Contains("not positive definite (pivot 1 of 3 is -2)"));
  auto umfpack = make_linear_solver({LinearSolverKind::umfpack, 1e-12, 0});
  umfpack->analyze(A);
  umfpack->factorize(A);
  const Vector x = umfpack->solve(Vector::Ones(3));
  CHECK_THAT(x[1], Catch::Matchers::WithinAbs(-0.5, 1e-15));
}

TEST_CASE("fem: the default solver factorises an indefinite matrix by LU and counts it",
          "[structure_fem][solver]") {
  // Issue 41 item 13: the default must not stop where LDL^T without pivoting does.
  CHECK(LinearSolverOptions{}.kind == LinearSolverKind::ldlt_or_lu);
  SparseMatrix A(3, 3);
  A.insert(0, 0) = 4.0;
  A.insert(1, 1) = -2.0;
  A.insert(2, 2) = 1.0;
  A.makeCompressed();
  SparseMatrix B = A;
  B.coeffRef(1, 1) = 2.0; // positive definite: LDL^T again, no fallback
  auto solver = make_linear_solver({});
  solver->analyze(A);
  solver->factorize(A);
  Vector x = solver->solve(Vector::Ones(3));
  CHECK(x[0] == 0.25);
  CHECK(x[1] == -0.5);
  CHECK(solver->fallbacks() == 1);
  solver->factorize(B);
  x = solver->solve(Vector::Ones(3));
  CHECK(x[1] == 0.5);
  CHECK(solver->fallbacks() == 1);
}

TEST_CASE("fem: past the buckling load CHOLMOD and LDLT stop, UMFPACK follows the straight path",
          "[structure_fem][solver]") {
  // Slender plane-stress column, EI = 1, Euler load of a cantilever pi^2 EI / (4 L^2) = 2.47;
  // an axial dead load of 4 on the perfect column leaves it straight with an indefinite K_T.
  Beam b;
  b.L = 1.0, b.h = 0.01, b.nu = 0.0, b.E = 12.0 / (b.h * b.h * b.h), b.ex = 40, b.ey = 2;
  b.plane = PlaneModel::plane_stress;
  const double P = 4.0;
  auto solve = [&](LinearSolverKind kind) {
    auto o = beam_options(b);
    o.linear_solver.kind = kind;
    Structure s(beam_mesh(b), o);
    s.set_external_forces(edge_traction_forces(s.mesh(), "right", {-P / b.h, 0.0}));
    s.solve_static({4});
    return Vector(s.displacement());
  };
  CHECK_THROWS_WITH(solve(LinearSolverKind::cholmod),
                    Catch::Contains("cholmod") && Catch::Contains("factorisation failed") &&
                        Catch::Contains("CHOLMOD status 1: not positive definite") &&
                        Catch::Contains("load step"));
  CHECK_THROWS_WITH(solve(LinearSolverKind::simplicial_ldlt),
                    Catch::Contains("simplicial_ldlt") &&
                        Catch::Contains("not positive definite") && Catch::Contains("load step"));
  const Vector u = solve(LinearSolverKind::umfpack);
  const Beam& c = b;
  const int tip = tip_node(beam_mesh(c), c);
  CHECK_THAT(u[2 * tip], Catch::Matchers::WithinRel(-P * b.L / (b.E * b.h), 1e-3));
  CHECK(std::abs(u[2 * tip + 1]) < 1e-12);
  // The default (ldlt_or_lu) takes the same path: LU where LDL^T refuses K_T.
  const Vector u_auto = solve(LinearSolverKind::ldlt_or_lu);
  CHECK((u_auto - u).norm() <= 1e-12 * u.norm());
}
