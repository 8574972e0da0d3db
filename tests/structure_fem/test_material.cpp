// Material laws: neo-Hookean stress and tangent against its energy, and plane-strain uniaxial
// compression past St. Venant–Kirchhoff's limit load (SVK crushes, neo-Hookean reaches the
// analytic stretch), with and without Newton's halving of inverting increments.
#include <catch2/catch.hpp>

#include <cmath>

#include "fsi/core/error.hpp"
#include "structure_fem/loads.hpp"
#include "structure_fem/rectangle_mesher.hpp"
#include "structure_fem/structure.hpp"

using namespace fsi::fem;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

/// The coarse sloshing beam's rubber (E' = 2.897e5 Pa, nu = 0.49, plane strain).
MaterialOptions sloshing_rubber(MaterialModel model) {
  return {2.897e5, 0.49, 988.9, PlaneModel::plane_strain, model};
}

struct Lame {
  double lambda, mu;
};
Lame lame(const MaterialOptions& o) {
  const double E = o.youngs_modulus, nu = o.poisson_ratio;
  return {E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)), E / (2.0 * (1.0 + nu))};
}

/// Plane-strain uniaxial stress (S22 = 0, F = diag(l1, l2, 1)) of neo-Hookean: the lateral
/// stretch l2 from mu (l2^2 - 1) + lambda ln(l1 l2) = 0 (bisection), and the nominal stress
/// P11 = mu (l1 - 1/l1) + lambda ln(l1 l2) / l1.
struct Uniaxial {
  double l2, P;
};
Uniaxial neo_hookean_uniaxial(const Lame& m, double l1) {
  auto g = [&](double l2) { return m.mu * (l2 * l2 - 1.0) + m.lambda * std::log(l1 * l2); };
  double lo = 1.0, hi = 10.0 / l1; // g(1) < 0 for l1 < 1, g(10/l1) > 0
  for (int i = 0; i < 200; ++i) (g(0.5 * (lo + hi)) < 0.0 ? lo : hi) = 0.5 * (lo + hi);
  const double l2 = 0.5 * (lo + hi);
  return {l2, m.mu * (l1 - 1.0 / l1) + m.lambda * std::log(l1 * l2) / l1};
}

/// A unit square, 2 x 2 rectangles, held by rollers on the left (u_x = 0) and bottom (u_y = 0),
/// under a dead compressive traction P on the right edge, statically solved in `load_steps`
/// increments (throws RunError if that fails). Returns the total halvings.
int compress(Structure& s, double P, int load_steps) {
  s.set_external_forces(edge_traction_forces(s.mesh(), "right", {P, 0.0}));
  int halvings = 0;
  for (const auto& r : s.solve_static({.load_steps = load_steps})) halvings += r.halvings;
  return halvings;
}

std::unique_ptr<Structure> material_block(MaterialModel model,
                                          int max_halvings = NewtonOptions{}.max_halvings) {
  StructureOptions o;
  o.material = sloshing_rubber(model);
  o.clamped = {{"left", true, false, {}, {}}, {"bottom", false, true, {}, {}}};
  o.newton.max_halvings = max_halvings;
  o.linear_solver.kind = LinearSolverKind::umfpack; // a trial tangent may be indefinite
  return std::make_unique<Structure>(make_rectangle_mesh({{0.0, 0.0}, 1.0, 1.0, 2, 2}), o);
}

} // namespace

TEST_CASE("fem: neo-Hookean stress and tangent are the derivatives of its energy",
          "[structure_fem][material]") {
  const auto nh = make_material(sloshing_rubber(MaterialModel::neo_hookean));
  fsi::Mat2 E;
  E << -0.21, 0.13, 0.13, 0.34; // large strain with shear, det C > 0
  const double h = 1e-6;
  const fsi::Mat2 S = nh->stress(E);
  const Mat3 D = nh->tangent(E);
  // Voigt (11, 22, 12) with engineering shear: dE12 = dE21 = gamma / 2.
  auto unit = [](int a) {
    fsi::Mat2 d = fsi::Mat2::Zero();
    if (a == 0) d(0, 0) = 1.0;
    if (a == 1) d(1, 1) = 1.0;
    if (a == 2) d(0, 1) = d(1, 0) = 0.5;
    return d;
  };
  const double S_voigt[3] = {S(0, 0), S(1, 1), S(0, 1)};
  for (int a = 0; a < 3; ++a) {
    const fsi::Mat2 dE = h * unit(a);
    const double dW = (nh->energy(E + dE) - nh->energy(E - dE)) / (2.0 * h);
    CHECK_THAT(S_voigt[a], WithinRel(dW, 1e-6));
    const fsi::Mat2 dS = (nh->stress(E + dE) - nh->stress(E - dE)) / (2.0 * h);
    const double dS_voigt[3] = {dS(0, 0), dS(1, 1), dS(0, 1)};
    for (int b = 0; b < 3; ++b) CHECK_THAT(D(b, a), WithinAbs(dS_voigt[b], 1e-6 * D.norm()));
  }
  // At E = 0 both laws have the linear-elastic tangent; the stress is zero.
  const auto svk = make_material(sloshing_rubber(MaterialModel::saint_venant_kirchhoff));
  CHECK((nh->tangent(fsi::Mat2::Zero()) - svk->tangent(fsi::Mat2::Zero())).norm() <
        1e-12 * svk->tangent(fsi::Mat2::Zero()).norm());
  CHECK(nh->stress(fsi::Mat2::Zero()).norm() == 0.0);
}

TEST_CASE("fem: neo-Hookean with plane stress is refused", "[structure_fem][material]") {
  MaterialOptions o = sloshing_rubber(MaterialModel::neo_hookean);
  o.plane = PlaneModel::plane_stress;
  CHECK_THROWS_AS(validate(o), fsi::InputError);
}

TEST_CASE("fem: uniaxial compression past the SVK limit load: SVK crushes, neo-Hookean reaches "
          "the analytic stretch",
          "[structure_fem][material]") {
  const Lame m = lame(sloshing_rubber(MaterialModel::neo_hookean));
  const double l1 = 0.4; // the stretch the neo-Hookean block must reach
  const Uniaxial exact = neo_hookean_uniaxial(m, l1);
  // SVK under S22 = 0: P11 = E* l1 (l1^2 - 1) / 2 with E* = 4 mu (lambda + mu) / (lambda + 2 mu),
  // whose largest compression is E* / (3 sqrt 3) at l1 = 1 / sqrt 3: no equilibrium beyond it.
  const double E_star = 4.0 * m.mu * (m.lambda + m.mu) / (m.lambda + 2.0 * m.mu);
  REQUIRE(-exact.P > 2.0 * E_star / (3.0 * std::sqrt(3.0)));
  CHECK_THROWS_AS(compress(*material_block(MaterialModel::saint_venant_kirchhoff), exact.P, 40),
                  fsi::RunError);

  const auto s = material_block(MaterialModel::neo_hookean);
  compress(*s, exact.P, 10);
  const auto& X = s->mesh().X;
  const Vector& u = s->displacement();
  for (std::size_t k = 0; k < X.size(); ++k) { // homogeneous: x = (l1 X, l2 Y), T6 exact
    CHECK_THAT(u[2 * static_cast<Eigen::Index>(k)], WithinAbs((l1 - 1.0) * X[k].x(), 1e-9));
    CHECK_THAT(u[2 * static_cast<Eigen::Index>(k) + 1],
               WithinAbs((exact.l2 - 1.0) * X[k].y(), 1e-9));
  }
}

TEST_CASE("fem: Newton halves an increment that inverts an element and converges",
          "[structure_fem][material][newton]") {
  const Lame m = lame(sloshing_rubber(MaterialModel::neo_hookean));
  const double l1 = 0.4;
  const Uniaxial exact = neo_hookean_uniaxial(m, l1);
  // In one load step the first Newton increment (the linear solution, u_x = P / E* at the
  // right edge, beyond -1) inverts every element.
  CHECK_THROWS_WITH(compress(*material_block(MaterialModel::neo_hookean, 0), exact.P, 1),
                    Catch::Contains("inverted element"));
  const auto s = material_block(MaterialModel::neo_hookean);
  CHECK(compress(*s, exact.P, 1) > 0);
  CHECK_THAT(s->displacement()[2 * 4], WithinAbs(l1 - 1.0, 1e-9));            // node 4: (1, 0)
  CHECK_THAT(s->displacement()[2 * 20 + 1], WithinAbs(exact.l2 - 1.0, 1e-9)); // node 20: (0, 1)
}
