// The von Mises stress of T10 elements (issue 44): the invariant sqrt(3/2 s : s) of rotated
// uniaxial and pure-shear Cauchy stresses, and the nodal values of a box under homogeneous finite
// deformations whose Cauchy stress is uniaxial (sigma_vm = sigma) or pure shear (sqrt(3) tau).
#include <catch2/catch.hpp>

#include <cmath>

#include <Eigen/Geometry>

#include "structure_fem/assembly.hpp"
#include "structure_fem/box_mesher.hpp"

using namespace fsi::fem;
using fsi::Mat3;
using fsi::Vec3;

namespace {

constexpr double E = 2.0e11, nu = 0.3;
constexpr double lambda = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)), mu = E / (2.0 * (1.0 + nu));

/// Rotations with every component non-zero, so no stress component stays zero.
const Mat3 R = Eigen::AngleAxisd(0.7, Vec3(1.0, 2.0, -0.5).normalized()).toRotationMatrix();
const Mat3 Q = Eigen::AngleAxisd(-1.1, Vec3(-0.3, 1.0, 0.8).normalized()).toRotationMatrix();

/// F = R V with the stretch V = sum_a sqrt(1 + 2 E_a) q_a (x) q_a (q_a the columns of Q): its
/// Green–Lagrange strain has the principal values E_a along q_a.
Mat3 deformation(const Vec3& E_principal) {
  const Vec3 stretch = (1.0 + 2.0 * E_principal.array()).sqrt();
  return R * Q * stretch.asDiagonal() * Q.transpose();
}

/// The largest relative deviation from `expected` of the nodal von Mises stress of a box of
/// T10 elements (St. Venant–Kirchhoff) under u = (F - I) X.
double nodal_deviation(const Mat3& F, double expected) {
  const TetMesh mesh = make_box_mesh({{0.1, -0.2, 0.3}, {1.0, 0.4, 0.3}, {3, 2, 2}});
  const auto law = make_material_3d({E, nu, 7800.0});
  const DofMap dofs(mesh, {});
  const AssemblerT10 assembler(mesh, *law, dofs);
  Vector u(3 * static_cast<Eigen::Index>(mesh.X.size()));
  for (std::size_t k = 0; k < mesh.X.size(); ++k)
    u.segment<3>(3 * static_cast<Eigen::Index>(k)) = (F - Mat3::Identity()) * mesh.X[k];
  return (assembler.nodal_von_mises(u).array() / expected - 1.0).abs().maxCoeff();
}

} // namespace

TEST_CASE("von Mises of rotated uniaxial and pure-shear Cauchy stresses",
          "[structure_fem][t10][von_mises]") {
  const double s = 3.0e8, tau = 1.2e8, p = -5.0e7; // p: a hydrostatic part, no deviator
  const Mat3 uniaxial = R * Vec3(s, 0.0, 0.0).asDiagonal() * R.transpose() + p * Mat3::Identity();
  Mat3 shear = Mat3::Zero();
  shear(0, 1) = shear(1, 0) = tau;
  CHECK(std::abs(fsi::materials::von_mises(uniaxial) / s - 1.0) < 1e-14);
  CHECK(std::abs(fsi::materials::von_mises(Mat3(R * shear * R.transpose() + p * Mat3::Identity())) /
                     (std::sqrt(3.0) * tau) -
                 1.0) < 1e-14);
}

TEST_CASE("T10: nodal von Mises of a finite uniaxial tension and a finite pure shear",
          "[structure_fem][t10][von_mises]") {
  // Uniaxial S = s q_1 (x) q_1: St. Venant–Kirchhoff's E = (s / E)(1, -nu, -nu) in the q basis,
  // sigma = F S F^T / J = (lambda_1^2 s / J) R q_1 (x) R q_1.
  const double s = 0.02 * E;
  const Vec3 E_uniaxial = s / E * Vec3(1.0, -nu, -nu);
  const Vec3 stretch_u = (1.0 + 2.0 * E_uniaxial.array()).sqrt();
  const double sigma = stretch_u[0] * stretch_u[0] * s / stretch_u.prod();
  const double uniaxial = nodal_deviation(deformation(E_uniaxial), sigma);

  // Pure shear: principal S_a = lambda tr E + 2 mu E_a with S_3 = 0, and E_2 found (bisection)
  // so that the principal Cauchy stresses (1 + 2 E_a) S_a / J of q_1 and q_2 are tau and -tau.
  const double E1 = 0.01;
  auto strains = [&](double E2) { return Vec3(E1, E2, -lambda * (E1 + E2) / (lambda + 2.0 * mu)); };
  auto cauchy = [&](const Vec3& Ea, int a) { // principal value a, times J
    return (1.0 + 2.0 * Ea[a]) * (lambda * Ea.sum() + 2.0 * mu * Ea[a]);
  };
  double lo = -0.05, hi = 0.0; // cauchy_1 + cauchy_2 < 0 at lo, > 0 at hi
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (cauchy(strains(mid), 0) + cauchy(strains(mid), 1) < 0.0 ? lo : hi) = mid;
  }
  const Vec3 E_shear = strains(0.5 * (lo + hi));
  const double J = (1.0 + 2.0 * E_shear.array()).sqrt().prod();
  const double tau = cauchy(E_shear, 0) / J;
  REQUIRE(std::abs(cauchy(E_shear, 1) / J + tau) < 1e-13 * tau);
  const double shear = nodal_deviation(deformation(E_shear), std::sqrt(3.0) * tau);
  WARN("T10 nodal von Mises: uniaxial sigma = " << sigma << " Pa, largest relative deviation "
                                                << uniaxial << "; pure shear tau = " << tau
                                                << " Pa, " << shear);
  CHECK(uniaxial < 1e-10);
  CHECK(shear < 1e-10);
}
