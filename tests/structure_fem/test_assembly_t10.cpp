// T10 assembly (issue 44): consistent mass and body force against the box's mass, face loads
// against the resultant of a pressure, and a patch test (uniaxial tension on a box with sliding
// faces) against the exact linear-elastic field, which quadratic tetrahedra reproduce.
#include <catch2/catch.hpp>

#include <array>

#include "structure_fem/assembly.hpp"
#include "structure_fem/box_mesher.hpp"
#include "structure_fem/linear_solver.hpp"
#include "structure_fem/loads.hpp"

using namespace fsi::fem;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {
const BoxMeshOptions box{{0.2, -0.1, 0.3}, {1.5, 0.4, 0.7}, {3, 2, 2}};
}

TEST_CASE("T10 assembly: mass and gravity of a box", "[structure_fem][t10][assembly]") {
  const TetMesh mesh = make_box_mesh(box);
  const auto law = make_material_3d({1e6, 0.3, 1200.0});
  const DofMap dofs(mesh, {});
  AssemblerT10 assembler(mesh, *law, dofs);
  const double m = 1200.0 * box.size.prod();
  const SparseMatrix M = assembler.mass();
  for (int c = 0; c < 3; ++c) { // a rigid translation along c: u^T M u = m
    Vector t = Vector::Zero(dofs.num_free());
    for (int k = 0; k < static_cast<int>(mesh.num_nodes()); ++k) t[3 * k + c] = 1.0;
    CHECK_THAT(t.dot(M * t), WithinRel(m, 1e-12));
  }
  const Vector f = assembler.gravity_forces({0.0, 0.0, -9.81});
  CHECK_THAT(f(Eigen::seqN(2, mesh.num_nodes(), 3)).sum(), WithinRel(-9.81 * m, 1e-12));
  CHECK_THAT(f(Eigen::seqN(0, mesh.num_nodes(), 3)).sum(), WithinAbs(0.0, 1e-9));
}

TEST_CASE("T10 loads: pressure resultants on the box faces", "[structure_fem][t10][loads]") {
  const TetMesh mesh = make_box_mesh(box);
  // Each side: area and outward orientation of its tagged faces, -p A n.
  const std::array<const char*, 6> sides{"x_min", "x_max", "y_min", "y_max", "z_min", "z_max"};
  for (int d = 0; d < 3; ++d)
    for (int side = 0; side < 2; ++side) {
      const Vector f = face_pressure_forces(mesh, sides[static_cast<std::size_t>(2 * d + side)],
                                            [](const fsi::Vec3&) { return 2.0e3; });
      const double area = box.size.prod() / box.size[d];
      for (int c = 0; c < 3; ++c)
        CHECK_THAT(f(Eigen::seqN(c, mesh.num_nodes(), 3)).sum(),
                   WithinAbs(c == d ? (side == 0 ? 2.0e3 : -2.0e3) * area : 0.0, 1e-9));
    }
  // A pressure linear in z on all six sides of the closed surface: the
  // resultant -integral p n dA = -integral grad p dV (Archimedes).
  Vector total = Vector::Zero(3 * static_cast<Eigen::Index>(mesh.num_nodes()));
  for (const char* side : sides)
    total +=
        face_pressure_forces(mesh, side, [](const fsi::Vec3& X) { return 1e3 * (2.0 - X.z()); });
  for (int c = 0; c < 3; ++c) {
    const double expected = c == 2 ? 1e3 * box.size.prod() : 0.0; // -grad p integrated (Archimedes)
    CHECK_THAT(total(Eigen::seqN(c, mesh.num_nodes(), 3)).sum(), WithinAbs(expected, 1e-9));
  }
}

TEST_CASE("T10 assembly: uniaxial tension patch test with sliding faces",
          "[structure_fem][t10][assembly]") {
  const TetMesh mesh = make_box_mesh(box);
  const double E = 2.0e9, nu = 0.3, sigma = 1.0e6;
  const auto law = make_material_3d({E, nu, 1000.0});
  const DofMap dofs(mesh, {{"x_min", {true, false, false}, {}},
                           {"y_min", {false, true, false}, {}},
                           {"z_min", {false, false, true}, {}}});
  AssemblerT10 assembler(mesh, *law, dofs);
  const Vector u0 = Vector::Zero(3 * static_cast<Eigen::Index>(mesh.num_nodes()));
  Vector f_int;
  SparseMatrix K = assembler.pattern();
  assembler.assemble(u0, f_int, &K); // the tangent at u = 0: linear elasticity
  CHECK(f_int.norm() == 0.0);
  const Vector f =
      face_traction_forces(mesh, "x_max", [&](const fsi::Vec3&) { return fsi::Vec3(sigma, 0, 0); });
  const auto solver = make_linear_solver({LinearSolverKind::cholmod});
  solver->analyze(K);
  solver->factorize(K);
  Vector u = Vector::Zero(u0.size());
  dofs.add_free(solver->solve(dofs.restrict_to_free(f)), u);
  const fsi::Vec3 strain(sigma / E, -nu * sigma / E, -nu * sigma / E); // uniaxial stress
  double worst = 0.0;
  for (std::size_t k = 0; k < mesh.num_nodes(); ++k) {
    const fsi::Vec3 exact = strain.cwiseProduct(mesh.X[k] - box.origin);
    worst = std::max(worst, (u.segment<3>(3 * static_cast<Eigen::Index>(k)) - exact).norm());
  }
  CHECK(worst < 1e-9 * strain.x() * box.size.x()); // exact up to round-off
}
