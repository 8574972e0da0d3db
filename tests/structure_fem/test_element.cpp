// T6 element and assembly: patch tests (uniform stress on a distorted mesh), consistent tangent,
// mass, von Mises, inverted elements.
#include <catch2/catch.hpp>

#include <cmath>

#include "fsi/core/error.hpp"
#include "fsi/core/parallel.hpp"
#include "structure_fem/assembly.hpp"
#include "structure_fem/loads.hpp"
#include "structure_fem/rectangle_mesher.hpp"
#include "structure_fem/structure.hpp"

using namespace fsi::fem;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

/// A 4 x 4 patch of the unit square whose interior corner nodes are moved by up to 0.2 of the
/// spacing; mid-nodes are put back at the midpoints of the (straight) sides.
Mesh distorted_patch() {
  Mesh mesh = make_rectangle_mesh({{0.0, 0.0}, 1.0, 1.0, 4, 4});
  const int n = 9; // nodes per row
  for (int j = 2; j < n - 1; j += 2)
    for (int i = 2; i < n - 1; i += 2) {
      const double s = std::sin(12.9898 * i + 78.233 * j), c = std::cos(4.1414 * i + 3.7 * j);
      mesh.X[static_cast<std::size_t>(j * n + i)] += 0.2 * 0.25 * fsi::Vec2(s, c);
    }
  for (const auto& el : mesh.elements)
    for (int s = 0; s < 3; ++s)
      mesh.X[static_cast<std::size_t>(el[static_cast<std::size_t>(s + 3)])] =
          0.5 * (mesh.X[static_cast<std::size_t>(el[static_cast<std::size_t>(s)])] +
                 mesh.X[static_cast<std::size_t>(el[static_cast<std::size_t>((s + 1) % 3)])]);
  validate_mesh(mesh);
  return mesh;
}

MaterialOptions steel(PlaneModel plane = PlaneModel::plane_strain) {
  return {2.0e11, 0.3, 7800.0, plane};
}

/// First Piola–Kirchhoff stress P = F S(E) of a homogeneous deformation.
fsi::Mat2 first_piola(const Material& m, const fsi::Mat2& F) {
  const fsi::Mat2 H = F - fsi::Mat2::Identity();
  return F * m.stress(0.5 * (H + H.transpose() + H.transpose() * H));
}

} // namespace

TEST_CASE("fem: patch test: homogeneous finite deformation gives uniform SVK stress",
          "[structure_fem][patch]") {
  const Mesh mesh = distorted_patch();
  const StVenantKirchhoff material(steel());
  const DofMap dofs(mesh, {});
  Assembler assembler(mesh, material, dofs);
  fsi::Mat2 F;
  F << 1.02, 0.15, -0.05, 0.97; // stretch, shear and rotation
  Vector u(2 * static_cast<Eigen::Index>(mesh.num_nodes()));
  for (std::size_t k = 0; k < mesh.num_nodes(); ++k)
    u.segment<2>(2 * static_cast<Eigen::Index>(k)) = (F - fsi::Mat2::Identity()) * mesh.X[k];
  Vector f_int;
  assembler.assemble(u, f_int, nullptr);
  // Exact: f_int equals the consistent nodal forces of the traction P N on the boundary.
  const fsi::Mat2 P = first_piola(material, F);
  const Vector expected = edge_traction_forces(mesh, "bottom", P * fsi::Vec2(0, -1)) +
                          edge_traction_forces(mesh, "right", P * fsi::Vec2(1, 0)) +
                          edge_traction_forces(mesh, "top", P * fsi::Vec2(0, 1)) +
                          edge_traction_forces(mesh, "left", P * fsi::Vec2(-1, 0));
  const double scale = P.norm();
  CHECK((f_int - expected).cwiseAbs().maxCoeff() / scale < 1e-10);

  // Nodal von Mises equals that of the analytic Cauchy stress everywhere.
  const double J = F.determinant();
  const fsi::Mat2 H = F - fsi::Mat2::Identity();
  const fsi::Mat2 E = 0.5 * (H + H.transpose() + H.transpose() * H);
  const fsi::Mat2 sigma = P * F.transpose() / J;
  const double s33 = material.stress_33(E) / J;
  const double vm =
      std::sqrt(0.5 * (std::pow(sigma(0, 0) - sigma(1, 1), 2) + std::pow(sigma(1, 1) - s33, 2) +
                       std::pow(s33 - sigma(0, 0), 2)) +
                3.0 * sigma(0, 1) * sigma(0, 1));
  const Vector nodal = assembler.nodal_von_mises(u);
  CHECK(((nodal.array() - vm).abs().maxCoeff()) / vm < 1e-10);
}

TEST_CASE("fem: patch test: static solve reproduces a uniform biaxial state",
          "[structure_fem][patch]") {
  for (auto plane : {PlaneModel::plane_strain, PlaneModel::plane_stress}) {
    StructureOptions o;
    o.material = steel(plane);
    o.clamped = {{"left", true, false, {}}, {"bottom", false, true, {}}}; // rollers
    o.newton.residual_rtol = 1e-12;
    Structure s(distorted_patch(), o);
    const double e1 = 2e-3, e2 = -1e-3; // exact u = (e1 X, e2 Y), finite-strain SVK
    fsi::Mat2 F;
    F << 1.0 + e1, 0.0, 0.0, 1.0 + e2;
    const StVenantKirchhoff material(o.material);
    const fsi::Mat2 P = first_piola(material, F);
    s.set_external_forces(edge_traction_forces(s.mesh(), "right", P * fsi::Vec2(1, 0)) +
                          edge_traction_forces(s.mesh(), "top", P * fsi::Vec2(0, 1)));
    s.solve_static({2});
    double err = 0.0;
    for (std::size_t k = 0; k < s.num_nodes(); ++k) {
      const fsi::Vec2 exact(e1 * s.mesh().X[k].x(), e2 * s.mesh().X[k].y());
      err = std::max(
          err, (s.displacement().segment<2>(2 * static_cast<Eigen::Index>(k)) - exact).norm());
    }
    CHECK(err / e1 < 1e-10);
  }
}

TEST_CASE("fem: element tangent is the derivative of the internal force",
          "[structure_fem][element]") {
  const ElementNodes X{fsi::Vec2(0.0, 0.0),  fsi::Vec2(1.0, 0.1),   fsi::Vec2(0.2, 0.9),
                       fsi::Vec2(0.5, 0.02), fsi::Vec2(0.62, 0.52), fsi::Vec2(0.08, 0.47)};
  const ElementT6 element(X);
  const StVenantKirchhoff material({1.0e6, 0.35, 1000.0, PlaneModel::plane_strain});
  Vec12 u;
  for (int i = 0; i < 12; ++i) u[i] = 0.05 * std::sin(1.7 * i + 0.3);
  Vec12 f;
  Mat12 K;
  REQUIRE(element.internal_force(u, material, f, &K) > 0.0);
  CHECK((K - K.transpose()).norm() / K.norm() < 1e-12);
  const double h = 1e-6;
  Mat12 K_fd;
  for (int j = 0; j < 12; ++j) {
    Vec12 up = u, um = u, fp, fm;
    up[j] += h, um[j] -= h;
    element.internal_force(up, material, fp, nullptr);
    element.internal_force(um, material, fm, nullptr);
    K_fd.col(j) = (fp - fm) / (2 * h);
    // The internal force is the gradient of the strain energy.
    const double dW =
        (element.strain_energy(up, material) - element.strain_energy(um, material)) / (2 * h);
    CHECK_THAT(dW, WithinAbs(f[j], 1e-6 * f.norm()));
  }
  CHECK((K - K_fd).norm() / K.norm() < 1e-7);
}

TEST_CASE("fem: consistent mass integrates rho exactly", "[structure_fem][element]") {
  const ElementNodes X{fsi::Vec2(0.0, 0.0), fsi::Vec2(2.0, 0.0), fsi::Vec2(0.0, 1.0),
                       fsi::Vec2(1.0, 0.0), fsi::Vec2(1.0, 0.5), fsi::Vec2(0.0, 0.5)};
  const Mat12 M = t6_mass(X, 3.0);
  Vec12 ex = Vec12::Zero();
  for (int k = 0; k < 6; ++k) ex[2 * k] = 1.0;
  CHECK_THAT(ex.dot(M * ex), WithinRel(3.0 * 1.0, 1e-13)); // rho * area
  // Corner-corner entry of the T6 mass: -rho A / 180.
  CHECK_THAT(M(0, 2), WithinRel(-3.0 / 180.0, 1e-12));
  CHECK_THAT(M(6, 6), WithinRel(3.0 * 8.0 / 45.0, 1e-12)); // mid-node: 8 rho A / 45
}

TEST_CASE("fem: an inverted element stops the run with RunError naming it",
          "[structure_fem][element]") {
  const Mesh mesh = make_rectangle_mesh({{0.0, 0.0}, 1.0, 1.0, 1, 1});
  const StVenantKirchhoff material({1.0e6, 0.3, 1000.0, PlaneModel::plane_strain});
  const DofMap dofs(mesh, {});
  Assembler assembler(mesh, material, dofs);
  Vector u = Vector::Zero(2 * static_cast<Eigen::Index>(mesh.num_nodes()));
  u[2 * 8 + 0] = -2.0, u[2 * 8 + 1] = -2.0; // pull the upper-right corner through the diagonal
  Vector f;
  CHECK_THROWS_WITH(assembler.assemble(u, f, nullptr),
                    Catch::Contains("element 1") && Catch::Contains("det F"));
}

TEST_CASE("fem: parallel assembly is bitwise identical to sequential", "[structure_fem][element]") {
  const Mesh mesh = make_rectangle_mesh({{0.0, 0.0}, 1.0, 0.2, 20, 4});
  const StVenantKirchhoff material({1.0e6, 0.3, 1000.0, PlaneModel::plane_strain});
  const DofMap dofs(mesh, {{"left", true, true, {}}});
  Assembler assembler(mesh, material, dofs);
  Vector u(2 * static_cast<Eigen::Index>(mesh.num_nodes()));
  for (Eigen::Index i = 0; i < u.size(); ++i) u[i] = 1e-3 * std::sin(0.37 * static_cast<double>(i));
  SparseMatrix K1 = assembler.pattern(), K2 = assembler.pattern();
  Vector f1, f2;
  fsi::set_sequential(true);
  assembler.assemble(u, f1, &K1);
  fsi::set_sequential(false);
  assembler.assemble(u, f2, &K2);
  CHECK((f1 - f2).cwiseAbs().maxCoeff() == 0.0);
  CHECK((K1 - K2).norm() == 0.0);
}
