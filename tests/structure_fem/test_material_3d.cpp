// The 3-D material laws (issue 42): stress and tangent against central differences of the energy
// and the stress at a random finite deformation, stress-free reference, and the small-strain
// limit against linear isotropic elasticity built from the bulk and shear moduli.
#include <catch2/catch.hpp>

#include <cmath>

#include "structure_fem/material.hpp"

using namespace fsi::fem;
using fsi::Mat3;
using fsi::materials::Mat6;
using fsi::materials::voigt_pairs;

namespace {

MaterialOptions rubber_3d(MaterialModel model) {
  return {2.897e5, 0.45, 988.9, PlaneModel::plane_strain, model};
}

/// A fixed pseudo-random F = I + 0.3 R, R with entries in [-1, 1] (det F = 1.0796 > 0), and its
/// Green–Lagrange strain.
Mat3 random_strain() {
  Mat3 R;
  R << 0.83, -0.41, 0.27, 0.12, -0.66, 0.94, -0.58, 0.31, 0.49;
  const Mat3 F = Mat3::Identity() + 0.3 * R;
  REQUIRE(F.determinant() > 0.5);
  return 0.5 * (F.transpose() * F - Mat3::Identity());
}

/// The strain variation of a unit change of Voigt component t (engineering shear: dE_kl = dE_lk
/// = 1/2).
Mat3 voigt_unit(int t) {
  const auto [k, l] = voigt_pairs<3>[static_cast<std::size_t>(t)];
  Mat3 d = Mat3::Zero();
  d(k, l) += k == l ? 1.0 : 0.5;
  if (k != l) d(l, k) += 0.5;
  return d;
}

Eigen::Matrix<double, 6, 1> voigt(const Mat3& S) {
  Eigen::Matrix<double, 6, 1> s;
  for (int r = 0; r < 6; ++r) {
    const auto [i, j] = voigt_pairs<3>[static_cast<std::size_t>(r)];
    s(r) = S(i, j);
  }
  return s;
}

/// Linear isotropic elasticity in Voigt form from the bulk modulus K = E / (3 (1 - 2 nu)) and the
/// shear modulus G = E / (2 (1 + nu)): C = (K - 2G/3) I (x) I + 2G II.
Mat6 lame_voigt(const MaterialOptions& o) {
  const double K = o.youngs_modulus / (3.0 * (1.0 - 2.0 * o.poisson_ratio));
  const double G = o.youngs_modulus / (2.0 * (1.0 + o.poisson_ratio));
  Mat6 C = Mat6::Zero();
  C.topLeftCorner<3, 3>().setConstant(K - 2.0 * G / 3.0);
  C.topLeftCorner<3, 3>().diagonal().array() += 2.0 * G;
  C.bottomRightCorner<3, 3>().diagonal().setConstant(G);
  return C;
}

} // namespace

TEST_CASE("materials 3-D: S = dW/dE and the tangent = dS/dE at a finite deformation",
          "[structure_fem][material][3d]") {
  for (const auto model : {MaterialModel::saint_venant_kirchhoff, MaterialModel::neo_hookean}) {
    CAPTURE(static_cast<int>(model));
    const auto law = make_material_3d(rubber_3d(model));
    const Mat3 E = random_strain();
    const Eigen::Matrix<double, 6, 1> S = voigt(law->stress(E));
    const Mat6 C = law->tangent(E);
    const double h = 1e-6;
    for (int t = 0; t < 6; ++t) {
      const Mat3 dE = h * voigt_unit(t);
      const double dW = (law->energy(E + dE) - law->energy(E - dE)) / (2.0 * h);
      CHECK(std::abs(S(t) - dW) <= 1e-6 * S.cwiseAbs().maxCoeff());
      const Eigen::Matrix<double, 6, 1> dS =
          (voigt(law->stress(E + dE)) - voigt(law->stress(E - dE))) / (2.0 * h);
      for (int r = 0; r < 6; ++r)
        CHECK(std::abs(C(r, t) - dS(r)) <= 1e-6 * C.cwiseAbs().maxCoeff());
    }
    CHECK((C - C.transpose()).cwiseAbs().maxCoeff() <= 1e-12 * C.cwiseAbs().maxCoeff());
  }
}

TEST_CASE("materials 3-D: stress-free reference and the small-strain limit is linear isotropic "
          "elasticity",
          "[structure_fem][material][3d]") {
  for (const auto model : {MaterialModel::saint_venant_kirchhoff, MaterialModel::neo_hookean}) {
    CAPTURE(static_cast<int>(model));
    const MaterialOptions o = rubber_3d(model);
    const auto law = make_material_3d(o);
    CHECK(law->energy(Mat3::Zero()) == 0.0);
    CHECK(law->stress(Mat3::Zero()).norm() == 0.0);
    CHECK(law->density() == o.density);
    const Mat6 C0 = lame_voigt(o);
    CHECK((law->tangent(Mat3::Zero()) - C0).cwiseAbs().maxCoeff() <=
          1e-8 * C0.cwiseAbs().maxCoeff());
    // The linearisation of S at E = 0 (central difference: the O(eps^2) terms cancel) is C0 : E.
    const Mat3 E = random_strain();
    const double eps = 1e-5;
    const Eigen::Matrix<double, 6, 1> dS =
        (voigt(law->stress(eps * E)) - voigt(law->stress(-eps * E))) / (2.0 * eps);
    Eigen::Matrix<double, 6, 1> e;
    for (int t = 0; t < 6; ++t) {
      const auto [k, l] = voigt_pairs<3>[static_cast<std::size_t>(t)];
      e(t) = k == l ? E(k, l) : 2.0 * E(k, l);
    }
    const Eigen::Matrix<double, 6, 1> linear = C0 * e;
    CHECK((dS - linear).cwiseAbs().maxCoeff() <= 1e-8 * linear.cwiseAbs().maxCoeff());
  }
}

TEST_CASE("materials 3-D: a hydrostatic stretch gives the closed-form neo-Hookean stress",
          "[structure_fem][material][3d]") {
  // F = s I: C = s^2 I, J = s^3, S = (mu (1 - 1/s^2) + lambda 3 ln s / s^2) I.
  const MaterialOptions o = rubber_3d(MaterialModel::neo_hookean);
  const double mu = o.youngs_modulus / (2.0 * (1.0 + o.poisson_ratio));
  const double lambda = o.youngs_modulus / (3.0 * (1.0 - 2.0 * o.poisson_ratio)) - 2.0 * mu / 3.0;
  const double s = 0.8;
  const Mat3 S = make_material_3d(o)->stress(0.5 * (s * s - 1.0) * Mat3::Identity());
  const double expected = mu * (1.0 - 1.0 / (s * s)) + lambda * 3.0 * std::log(s) / (s * s);
  CHECK_THAT(S(0, 0), Catch::Matchers::WithinRel(expected, 1e-12));
  CHECK_THAT(S(2, 2), Catch::Matchers::WithinRel(expected, 1e-12));
  CHECK(std::abs(S(0, 1)) <= 1e-12 * std::abs(expected));
}
