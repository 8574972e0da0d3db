// A clamped square plate under uniform pressure as a T10 solid (issue 44): the centre deflection
// on three meshes, the observed order, and the finest and the Richardson-extrapolated values
// against the thick-plate (Mindlin) value, with the thin-plate (Kirchhoff) value beside it. The
// solid is clamped on its whole side faces, which is not quite Mindlin's clamped edge (w = 0,
// rotations 0 at the mid-surface); its load acts on the top face, not the mid-surface.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>

#include "structure_fem/assembly.hpp"
#include "structure_fem/box_mesher.hpp"
#include "structure_fem/linear_solver.hpp"
#include "structure_fem/loads.hpp"

using namespace fsi::fem;

namespace {

constexpr double a = 1.0, h = 0.1, E_plate = 2.0e11, nu_plate = 0.3, q = 1.0e5; // a/h = 10
const double D = E_plate * h * h * h / (12.0 * (1.0 - nu_plate * nu_plate));    // flexural rigidity
/// Centre deflection w D / (q a^4) of the clamped square plate, nu = 0.3: Kirchhoff (Timoshenko &
/// Woinowsky-Krieger, Theory of Plates and Shells, 2nd ed., sec. 44, Table 35), and Mindlin with
/// k = 5/6 at a/h = 10 (Legendre–Ritz solution of Mindlin's equations,
/// scripts/mindlin_square_plate.py, 8 digits; it gives 0.00126532 as h -> 0).
constexpr double kirchhoff_coefficient = 0.00126, mindlin_coefficient = 0.00150463;

/// Centre deflection (downwards, at the mid-surface) of the quarter plate [0, a/2]^2 x [0, h]
/// meshed by n x n x n/5 cells (cubes of side a/(10 n/5)): faces x_min and y_min clamped, x_max
/// and y_max symmetry planes (u_x = 0, u_y = 0), pressure q on z_max; K(0) u = f.
double centre_deflection(int n) {
  const int nz = n / 5;
  const TetMesh mesh = make_box_mesh({{0.0, 0.0, 0.0}, {0.5 * a, 0.5 * a, h}, {n, n, nz}});
  const auto law = make_material_3d({E_plate, nu_plate, 7800.0});
  const DofMap dofs(mesh, {{"x_min", {true, true, true}, {}},
                           {"y_min", {true, true, true}, {}},
                           {"x_max", {true, false, false}, {}},
                           {"y_max", {false, true, false}, {}}});
  AssemblerT10 assembler(mesh, *law, dofs);
  Vector f_int, u = Vector::Zero(3 * static_cast<Eigen::Index>(mesh.X.size()));
  SparseMatrix K = assembler.pattern();
  assembler.assemble(u, f_int, &K);
  const Vector f = face_pressure_forces(mesh, "z_max", [](const fsi::Vec3&) { return q; });
  const auto solver = make_linear_solver({LinearSolverKind::cholmod});
  solver->analyze(K);
  solver->factorize(K);
  dofs.add_free(solver->solve(dofs.restrict_to_free(f)), u);
  // The node at (a/2, a/2, h/2): lattice indices (2n, 2n, nz), x fastest, then y, then z.
  const int centre = 2 * n + (2 * n + 1) * (2 * n + (2 * n + 1) * nz);
  REQUIRE((mesh.X[centre] - fsi::Vec3(0.5 * a, 0.5 * a, 0.5 * h)).norm() < 1e-12);
  return -u[3 * centre + 2];
}

} // namespace

TEST_CASE("T10: clamped square plate centre deflection converges to the Mindlin value",
          "[structure_fem][t10][plate][convergence]") {
  const std::array<int, 3> n{5, 10, 20}; // quarter plate: 5 x 5 x 1 ... 20 x 20 x 4 cells
  std::array<double, 3> w{};
  for (std::size_t i = 0; i < 3; ++i) w[i] = centre_deflection(n[i]);
  // Observed order from three meshes halving the spacing, and Richardson's extrapolation.
  const double p = std::log2((w[1] - w[0]) / (w[2] - w[1]));
  const double extrapolated = w[2] + (w[2] - w[1]) / (std::pow(2.0, p) - 1.0);
  const double kirchhoff = kirchhoff_coefficient * q * std::pow(a, 4) / D;
  const double mindlin = mindlin_coefficient * q * std::pow(a, 4) / D;
  WARN("clamped plate a/h = 10, w D/(q a^4): "
       << w[0] * D / q << ", " << w[1] * D / q << ", " << w[2] * D / q << "; order " << p
       << "; finest vs Mindlin " << w[2] / mindlin - 1.0 << ", extrapolated "
       << extrapolated * D / q << " vs Mindlin " << mindlin * D / q << ": "
       << extrapolated / mindlin - 1.0 << "; Kirchhoff " << kirchhoff * D / q);
  // Quadratic elements give O(h^3) or better on a smooth solution; the stress singularity where
  // the clamped faces meet the free top and bottom faces (Williams 1952) lowers the asymptotic
  // rate, so only first order or better is required.
  CHECK(p > 1.0);
  CHECK_THAT(w[2], Catch::Matchers::WithinRel(mindlin, 0.02));
  CHECK_THAT(extrapolated, Catch::Matchers::WithinRel(mindlin, 0.02));
}
