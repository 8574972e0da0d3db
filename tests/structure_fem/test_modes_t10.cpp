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
