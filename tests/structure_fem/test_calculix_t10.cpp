// A linear T10 cantilever (box mesher, clamped at x = 0, tip load) assembled and solved here and
// by CalculiX with C3D10 elements on the same mesh and nodal loads (issue 44).
#include <catch2/catch.hpp>

#include <sstream>
#include <vector>

#include <Eigen/SparseCore>

#include "calculix.hpp"
#include "structure_fem/box_mesher.hpp"
#include "structure_fem/element_t10.hpp"
#include "structure_fem/linear_solver.hpp"

using namespace fsi::fem;
using fem_test::ccx_available;
using fem_test::run_ccx_deck;

namespace {

struct Cantilever {
  double L = 1.0, h = 0.1, E = 2.0e11, nu = 0.3, P = 1.0e4; ///< P: total tip load along -z [N]
  TetMesh mesh = make_box_mesh({{0.0, 0.0, 0.0}, {1.0, 0.1, 0.1}, {20, 2, 2}});
  std::vector<int> clamped, tip; ///< nodes at x = 0 and x = L
  Cantilever() {
    for (std::size_t k = 0; k < mesh.X.size(); ++k) {
      if (mesh.X[k].x() == 0.0) clamped.push_back(static_cast<int>(k));
      if (mesh.X[k].x() == L) tip.push_back(static_cast<int>(k));
    }
  }
};

/// The mean tip u_z of the linear problem K u = f on the free dofs: K from ElementT10 at u = 0
/// (St. Venant–Kirchhoff: linear isotropic elasticity), solved by CHOLMOD.
double tip_deflection(const Cantilever& c) {
  const auto n = static_cast<Eigen::Index>(c.mesh.X.size());
  std::vector<Eigen::Index> dof(static_cast<std::size_t>(3 * n), 0); // free index or -1
  for (int k : c.clamped)
    for (int d = 0; d < 3; ++d) dof[static_cast<std::size_t>(3 * k + d)] = -1;
  Eigen::Index free = 0;
  for (auto& d : dof)
    if (d == 0) d = free++;
  const auto law = make_material_3d({c.E, c.nu, 7800.0});
  std::vector<Eigen::Triplet<double>> triplets;
  for (const auto& element : c.mesh.elements) {
    TetNodes X;
    for (std::size_t a = 0; a < 10; ++a) X[a] = c.mesh.X[static_cast<std::size_t>(element[a])];
    Vec30 f;
    Mat30 K;
    ElementT10(X).internal_force(Vec30::Zero(), *law, f, &K);
    for (int i = 0; i < 30; ++i)
      for (int j = 0; j < 30; ++j) {
        const auto di =
            dof[static_cast<std::size_t>(3 * element[static_cast<std::size_t>(i / 3)] + i % 3)];
        const auto dj =
            dof[static_cast<std::size_t>(3 * element[static_cast<std::size_t>(j / 3)] + j % 3)];
        if (di >= 0 && dj >= 0) triplets.emplace_back(di, dj, K(i, j));
      }
  }
  SparseMatrix K(free, free);
  K.setFromTriplets(triplets.begin(), triplets.end());
  Vector f = Vector::Zero(free);
  for (int k : c.tip)
    f[dof[static_cast<std::size_t>(3 * k + 2)]] = -c.P / static_cast<double>(c.tip.size());
  const auto solver = make_linear_solver({LinearSolverKind::cholmod});
  solver->analyze(K);
  solver->factorize(K);
  const Vector u = solver->solve(f);
  double sum = 0.0;
  for (int k : c.tip) sum += u[dof[static_cast<std::size_t>(3 * k + 2)]];
  return sum / static_cast<double>(c.tip.size());
}

/// The same mesh, clamp and nodal loads as a CalculiX deck (C3D10, *STATIC).
std::string ccx_deck(const Cantilever& c) {
  std::ostringstream inp;
  inp.precision(17);
  inp << "*NODE\n";
  for (std::size_t k = 0; k < c.mesh.X.size(); ++k)
    inp << k + 1 << ", " << c.mesh.X[k].x() << ", " << c.mesh.X[k].y() << ", " << c.mesh.X[k].z()
        << "\n";
  // C3D10 lists the edge nodes (1-3) and (2-3) (0-based vertices) in the other order.
  constexpr std::array<std::size_t, 10> ccx_order{0, 1, 2, 3, 4, 5, 6, 7, 9, 8};
  inp << "*ELEMENT, TYPE=C3D10, ELSET=EALL\n";
  for (std::size_t e = 0; e < c.mesh.elements.size(); ++e) {
    inp << e + 1;
    for (std::size_t a : ccx_order) inp << ", " << c.mesh.elements[e][a] + 1;
    inp << "\n";
  }
  inp << "*NSET, NSET=FIX\n";
  for (int k : c.clamped) inp << k + 1 << ",\n";
  inp << "*NSET, NSET=TIP\n";
  for (int k : c.tip) inp << k + 1 << ",\n";
  inp << "*BOUNDARY\nFIX, 1, 3\n*MATERIAL, NAME=SOLID\n*ELASTIC\n" << c.E << ", " << c.nu << "\n";
  inp << "*SOLID SECTION, ELSET=EALL, MATERIAL=SOLID\n*STEP\n*STATIC\n*CLOAD\n";
  for (int k : c.tip) inp << k + 1 << ", 3, " << -c.P / static_cast<double>(c.tip.size()) << "\n";
  inp << "*NODE PRINT, NSET=TIP\nU\n*END STEP\n";
  return inp.str();
}

} // namespace

TEST_CASE("T10: linear cantilever tip deflection agrees with CalculiX C3D10",
          "[structure_fem][calculix][t10]") {
  if (!ccx_available()) {
    WARN("ccx not found: skipped");
    return;
  }
  const Cantilever c; // L = 1, 0.1 x 0.1 section, 20 x 2 x 2 cells (480 T10)
  const double ours = tip_deflection(c);
  double theirs = 0.0;
  for (const auto& [node, u] : run_ccx_deck(ccx_deck(c), "cantilever_t10")) theirs += u.z();
  theirs /= static_cast<double>(c.tip.size());
  const double euler_bernoulli =
      -c.P * c.L * c.L * c.L / (3.0 * c.E * c.h * c.h * c.h * c.h / 12.0);
  WARN("T10 cantilever tip u_z: structure_fem "
       << ours << ", CalculiX C3D10 " << theirs << ", relative difference "
       << (ours - theirs) / theirs << "; Euler-Bernoulli " << euler_bernoulli);
  CHECK_THAT(ours, Catch::Matchers::WithinRel(theirs, 0.005));
}
