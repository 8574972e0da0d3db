// A T10 cantilever (box mesher, clamped face x_min, a uniform shear traction on face x_max)
// solved through the library and by CalculiX with C3D10 elements on the same mesh and the same
// consistent nodal loads (issue 44): linear (the tangent at u = 0) and with NLGEOM (StructureT10,
// St. Venant–Kirchhoff, which is CalculiX's *ELASTIC under NLGEOM) at a tip rotation above 30°.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <sstream>
#include <vector>

#include "calculix.hpp"
#include "structure_fem/assembly.hpp"
#include "structure_fem/box_mesher.hpp"
#include "structure_fem/linear_solver.hpp"
#include "structure_fem/loads.hpp"
#include "structure_fem/structure.hpp"

using namespace fsi::fem;
using fem_test::ccx_available;
using fem_test::run_ccx_deck;

namespace {

struct Cantilever {
  double L = 1.0, h = 0.1, E = 2.0e11, nu = 0.3;
  double P; ///< total tip load along -z [N]
  TetMesh mesh = make_box_mesh({{0.0, 0.0, 0.0}, {1.0, 0.1, 0.1}, {20, 2, 2}}); // 480 T10
  std::vector<int> tip = mesh.node_set("x_max");
  Vector f; ///< consistent nodal forces of the traction -P / h^2 e_z on x_max
  explicit Cantilever(double P_) : P(P_) {
    f = face_traction_forces(mesh, "x_max",
                             [&](const fsi::Vec3&) { return fsi::Vec3(0.0, 0.0, -P / (h * h)); });
  }
  MaterialOptions material() const { return {E, nu, 7800.0}; }
  /// Mean of component c of a node array over the tip nodes.
  double tip_mean(const Vector& u, int c) const {
    double sum = 0.0;
    for (int k : tip) sum += u[3 * k + c];
    return sum / static_cast<double>(tip.size());
  }
  /// Rotation of the tip section: the angle between the deformed and the reference segment
  /// from (L, h/2, 0) to (L, h/2, h) [rad].
  double tip_rotation(const Vector& u) const {
    int bottom = -1, top = -1;
    for (int k : tip) {
      const auto& X = mesh.X[static_cast<std::size_t>(k)];
      if (X.y() == 0.5 * h && X.z() == 0.0) bottom = k;
      if (X.y() == 0.5 * h && X.z() == h) top = k;
    }
    const fsi::Vec3 d = fsi::Vec3(0, 0, h) + u.segment<3>(3 * top) - u.segment<3>(3 * bottom);
    return std::acos(d.z() / d.norm());
  }
};

/// The same mesh, clamp and nodal loads as a CalculiX deck (C3D10, *STATIC, NLGEOM if asked).
std::string ccx_deck(const Cantilever& c, bool nlgeom) {
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
  for (int k : c.mesh.node_set("x_min")) inp << k + 1 << ",\n";
  inp << "*NSET, NSET=TIP\n";
  for (int k : c.tip) inp << k + 1 << ",\n";
  inp << "*BOUNDARY\nFIX, 1, 3\n*MATERIAL, NAME=SOLID\n*ELASTIC\n" << c.E << ", " << c.nu << "\n";
  inp << "*SOLID SECTION, ELSET=EALL, MATERIAL=SOLID\n";
  inp << (nlgeom ? "*STEP, NLGEOM, INC=1000\n*STATIC\n0.05, 1.0, 1e-5, 0.05\n"
                 : "*STEP\n*STATIC\n");
  inp << "*CLOAD\n";
  inp.precision(12); // CalculiX reads fields of at most 20 characters
  for (Eigen::Index d = 0; d < c.f.size(); ++d)
    if (c.f[d] != 0.0) inp << d / 3 + 1 << ", " << d % 3 + 1 << ", " << c.f[d] << "\n";
  inp << "*NODE PRINT, NSET=TIP\nU\n*END STEP\n";
  return inp.str();
}

/// CalculiX's tip displacements as a node array (zero elsewhere); the last increment's.
Vector ccx_tip_displacements(const Cantilever& c, bool nlgeom, const std::string& name) {
  Vector u = Vector::Zero(c.f.size());
  for (const auto& [node, u_k] : run_ccx_deck(ccx_deck(c, nlgeom), name))
    u.segment<3>(3 * node) = u_k;
  return u;
}

} // namespace

TEST_CASE("T10: linear cantilever tip deflection agrees with CalculiX C3D10",
          "[structure_fem][calculix][t10]") {
  if (!ccx_available()) {
    WARN("ccx not found: skipped");
    return;
  }
  const Cantilever c(1.0e4);
  // K(0) u = f through the library: DofMap, AssemblerT10, CHOLMOD.
  const auto law = make_material_3d(c.material());
  const DofMap dofs(c.mesh, {{"x_min", {true, true, true}, {}}});
  AssemblerT10 assembler(c.mesh, *law, dofs);
  Vector f_int, u = Vector::Zero(c.f.size());
  SparseMatrix K = assembler.pattern();
  assembler.assemble(u, f_int, &K);
  const auto solver = make_linear_solver({LinearSolverKind::cholmod});
  solver->analyze(K);
  solver->factorize(K);
  dofs.add_free(solver->solve(dofs.restrict_to_free(c.f)), u);
  const double ours = c.tip_mean(u, 2);
  const double theirs = c.tip_mean(ccx_tip_displacements(c, false, "cantilever_t10"), 2);
  const double euler_bernoulli = -c.P * std::pow(c.L, 3) / (3.0 * c.E * std::pow(c.h, 4) / 12.0);
  WARN("T10 cantilever tip u_z: structure_fem "
       << ours << ", CalculiX C3D10 " << theirs << ", relative difference "
       << (ours - theirs) / theirs << "; Euler-Bernoulli " << euler_bernoulli);
  CHECK_THAT(ours, Catch::Matchers::WithinRel(theirs, 0.005));
}

TEST_CASE("T10: cantilever at large deflection agrees with CalculiX C3D10 NLGEOM",
          "[structure_fem][calculix][t10][nlgeom]") {
  if (!ccx_available()) {
    WARN("ccx not found: skipped");
    return;
  }
  const Cantilever c(3.0e6); // P L^2 / (E I) = 1.8
  StructureT10Options o;
  o.material = c.material();
  o.clamped = {{"x_min", {true, true, true}, {}}};
  StructureT10 s(c.mesh, o);
  s.set_external_forces(c.f);
  int iterations = 0;
  for (const auto& r : s.solve_static({10})) iterations += r.iterations;
  const Vector& u = s.displacement();
  const Vector u_ccx = ccx_tip_displacements(c, true, "cantilever_t10_nlgeom");
  const double rotation = c.tip_rotation(u) * 180.0 / std::numbers::pi;
  WARN("T10 NLGEOM cantilever (10 load steps, "
       << iterations << " Newton iterations): tip rotation " << rotation << " deg (CalculiX "
       << c.tip_rotation(u_ccx) * 180.0 / std::numbers::pi << "); tip u_z " << c.tip_mean(u, 2)
       << " vs " << c.tip_mean(u_ccx, 2) << " (" << (c.tip_mean(u, 2) / c.tip_mean(u_ccx, 2) - 1.0)
       << "), u_x " << c.tip_mean(u, 0) << " vs " << c.tip_mean(u_ccx, 0) << " ("
       << (c.tip_mean(u, 0) / c.tip_mean(u_ccx, 0) - 1.0) << ")");
  CHECK(rotation > 30.0);
  CHECK_THAT(c.tip_mean(u, 2), Catch::Matchers::WithinRel(c.tip_mean(u_ccx, 2), 0.01));
  CHECK_THAT(c.tip_mean(u, 0), Catch::Matchers::WithinRel(c.tip_mean(u_ccx, 0), 0.01));
}
