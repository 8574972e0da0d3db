// The first three bending frequencies of a slender T10 cantilever (issue 44) against
// Euler–Bernoulli beam theory: omega_n = (beta_n L)^2 / L^2 sqrt(E I / (rho A)).
#include <catch2/catch.hpp>

#include <cmath>

#include "structure_fem/assembly.hpp"
#include "structure_fem/box_mesher.hpp"
#include "structure_fem/modal.hpp"

using namespace fsi::fem;

TEST_CASE("T10 cantilever: first three bending frequencies within 1 % of beam theory",
          "[structure_fem][t10][modes]") {
  // L / h = 60: the shear and rotary-inertia corrections of the third mode stay well below 1 %.
  // The section is 2h wide, so the modes bending across the width are twice as high.
  const double L = 1.0, h = L / 60.0, b = 2.0 * h, E = 2.0e11, nu = 0.3, rho = 7800.0;
  const TetMesh mesh = make_box_mesh({{0.0, 0.0, 0.0}, {L, b, h}, {60, 2, 2}});
  const auto law = make_material_3d({E, nu, rho});
  const DofMap dofs(mesh, {{"x_min", {true, true, true}, {}}});
  AssemblerT10 assembler(mesh, *law, dofs);
  Vector f_int;
  SparseMatrix K = assembler.pattern();
  assembler.assemble(Vector::Zero(3 * static_cast<Eigen::Index>(mesh.num_nodes())), f_int, &K);
  const Modes modes = lowest_modes(K, assembler.mass(), 5, 1e-8); // z1, y1, z2, y2, z3
  // The modes bending in the thin direction: u_z dominant.
  std::vector<double> omega;
  for (Eigen::Index i = 0; i < modes.shape.cols(); ++i) {
    Vector u = Vector::Zero(f_int.size());
    dofs.add_free(modes.shape.col(i), u);
    double uz2 = 0.0, rest = 0.0;
    for (Eigen::Index k = 0; k < u.size(); ++k) (k % 3 == 2 ? uz2 : rest) += u[k] * u[k];
    if (uz2 > rest) omega.push_back(std::sqrt(modes.omega_squared[i]));
  }
  REQUIRE(omega.size() >= 3);
  const double beta_L[3] = {1.8751040687, 4.6940911330, 7.8547574382}; // cos x cosh x = -1
  const double stiffness = std::sqrt(E * (b * h * h * h / 12.0) / (rho * b * h));
  for (int n = 0; n < 3; ++n) {
    const double beam = beta_L[n] * beta_L[n] / (L * L) * stiffness;
    WARN("bending mode " << n + 1 << ": T10 " << omega[static_cast<std::size_t>(n)]
                         << " rad/s, Euler-Bernoulli " << beam << " rad/s, relative "
                         << omega[static_cast<std::size_t>(n)] / beam - 1.0);
    CHECK_THAT(omega[static_cast<std::size_t>(n)], Catch::Matchers::WithinRel(beam, 0.01));
  }
}

namespace {

/// J of a b x h rectangle (b >= h) in Saint-Venant torsion (Timoshenko & Goodier, Theory of
/// Elasticity, sec. 109): (b h^3 / 3) [1 - (192 / pi^5) (h / b) sum_{n odd} tanh(n pi b / 2h) /
/// n^5].
double torsion_constant(double b, double h) {
  double sum = 0.0;
  for (int n = 1; n < 40; n += 2)
    sum += std::tanh(n * M_PI * b / (2.0 * h)) / std::pow(static_cast<double>(n), 5);
  return b * h * h * h / 3.0 * (1.0 - 192.0 / std::pow(M_PI, 5) * (h / b) * sum);
}

/// The lowest omega of each family of a cantilever along x: bending in z (u_z carries > 90 % of
/// sum u^2), bending in y (u_y > 90 %), axial (u_x > 90 %), torsion (u_x < 1 %, u_y and u_z
/// each > 10 %). Zero where no mode of the family was found.
struct Families {
  double bending_z = 0.0, bending_y = 0.0, axial = 0.0, torsion = 0.0;
};

Families lowest_per_family(const TetMesh& mesh, const DofMap& dofs, const Modes& modes) {
  Families f;
  auto first = [](double& slot, double omega) {
    if (slot == 0.0) slot = omega;
  };
  for (Eigen::Index i = 0; i < modes.shape.cols(); ++i) {
    Vector u = Vector::Zero(3 * static_cast<Eigen::Index>(mesh.num_nodes()));
    dofs.add_free(modes.shape.col(i), u);
    double e[3] = {0.0, 0.0, 0.0};
    for (Eigen::Index k = 0; k < u.size(); ++k) e[k % 3] += u[k] * u[k];
    const double total = e[0] + e[1] + e[2], omega = std::sqrt(modes.omega_squared[i]);
    if (e[2] > 0.9 * total) first(f.bending_z, omega);
    if (e[1] > 0.9 * total) first(f.bending_y, omega);
    if (e[0] > 0.9 * total) first(f.axial, omega);
    if (e[0] < 0.01 * total && e[1] > 0.1 * total && e[2] > 0.1 * total) first(f.torsion, omega);
  }
  return f;
}

} // namespace

TEST_CASE("T10 cantilever: both bending planes, torsion and the axial mode converge from above "
          "to beam and rod theory",
          "[structure_fem][t10][modes][convergence]") {
  // A 0.06 x 0.04 section (L / b = 17, L / h = 25): Euler–Bernoulli bending in each plane,
  // Saint-Venant torsion omega = (pi / 2L) sqrt(G J / (rho I_p)) (the clamp's restrained warping
  // stiffens it slightly), rod theory omega = (pi / 2L) sqrt(E / rho). Two meshes (cubic cells
  // of 0.02 and 0.01 m): conforming elements with the consistent mass bound every omega from
  // above, so each must fall from the coarse to the fine mesh.
  const double L = 1.0, b = 0.06, h = 0.04, E = 2.0e11, nu = 0.3, rho = 7800.0;
  const double G = E / (2.0 * (1.0 + nu)), beta_L = 1.8751040687;
  const Families theory{
      beta_L * beta_L / (L * L) * std::sqrt(E * h * h / (12.0 * rho)),
      beta_L * beta_L / (L * L) * std::sqrt(E * b * b / (12.0 * rho)),
      M_PI / (2.0 * L) * std::sqrt(E / rho),
      M_PI / (2.0 * L) *
          std::sqrt(G * torsion_constant(b, h) / (rho * b * h * (b * b + h * h) / 12.0))};
  const auto law = make_material_3d({E, nu, rho});
  std::vector<Families> levels;
  for (const int n : {1, 2}) {
    const TetMesh mesh = make_box_mesh({{0.0, 0.0, 0.0}, {L, b, h}, {50 * n, 3 * n, 2 * n}});
    const DofMap dofs(mesh, {{"x_min", {true, true, true}, {}}});
    AssemblerT10 assembler(mesh, *law, dofs);
    Vector f_int;
    SparseMatrix K = assembler.pattern();
    assembler.assemble(Vector::Zero(3 * static_cast<Eigen::Index>(mesh.num_nodes())), f_int, &K);
    // z1, y1, z2, y2, z3, torsion, y3, z4, axial: 10 modes reach all four families.
    levels.push_back(lowest_per_family(mesh, dofs, lowest_modes(K, assembler.mass(), 10, 1e-8)));
  }
  const auto check = [&](const char* name, double Families::*family, double tolerance) {
    const double coarse = levels[0].*family, fine = levels[1].*family, exact = theory.*family;
    WARN(name << ": T10 " << coarse << " / " << fine << " rad/s, theory " << exact << ", relative "
              << coarse / exact - 1.0 << " / " << fine / exact - 1.0);
    REQUIRE(fine > 0.0);
    CHECK(fine < coarse);
    CHECK_THAT(fine, Catch::Matchers::WithinRel(exact, tolerance));
  };
  check("bending in z", &Families::bending_z, 0.01);
  check("bending in y", &Families::bending_y, 0.01);
  check("axial", &Families::axial, 0.005);
  check("torsion", &Families::torsion, 0.01);
}
