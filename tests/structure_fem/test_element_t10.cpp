// The T10 element (issue 44): shape functions, quadrature exactness, curved volume against a
// closed form, the patch test at a finite homogeneous deformation, zero force under a large rigid
// rotation, the tangent against finite differences of the internal force, and the mass matrix.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

#include "structure_fem/element_t10.hpp"
#include "structure_fem/shape_t10.hpp"

using namespace fsi::fem;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using fsi::Mat3;
using fsi::Vec3;

namespace {

/// An affine map X = A xi + X0 of the reference tetrahedron (det A = 0.9275).
Mat3 affine() {
  Mat3 A;
  A << 1.1, 0.2, -0.1, 0.05, 0.9, 0.25, -0.15, 0.1, 0.95;
  return A;
}
const Vec3 X0(0.3, -0.2, 0.5);

/// The element nodes of the map X(xi) at the reference nodes (exact for a quadratic map).
template <class Map> TetNodes nodes_of(Map map) {
  TetNodes X;
  for (std::size_t k = 0; k < 10; ++k) {
    const auto& p = t10_node_parent[k];
    X[k] = map(Vec3(p[0], p[1], p[2]));
  }
  return X;
}

TetNodes straight() {
  return nodes_of([](const Vec3& xi) { return Vec3(affine() * xi + X0); });
}

/// A curved tetrahedron: X = A phi(xi) + X0 with the quadratic phi = (xi (1 + a eta),
/// eta (1 + b zeta), zeta (1 + c xi)), whose det(d phi / d xi) = (1 + a eta)(1 + b zeta)(1 + c xi)
/// + abc xi eta zeta.
constexpr double ca = 0.3, cb = -0.2, cc = 0.25;
TetNodes curved() {
  return nodes_of([](const Vec3& p) {
    return Vec3(affine() * Vec3(p.x() * (1 + ca * p.y()), p.y() * (1 + cb * p.z()),
                                p.z() * (1 + cc * p.x())) +
                X0);
  });
}
/// Its volume from the monomial integrals over the reference tetrahedron,
/// integral xi^i eta^j zeta^k = i! j! k! / (i + j + k + 3)!.
double curved_volume() {
  return affine().determinant() *
         (1.0 / 6.0 + (ca + cb + cc) / 24.0 + (ca * cb + ca * cc + cb * cc) / 120.0 +
          2.0 * ca * cb * cc / 720.0);
}

double factorial(int n) {
  return n <= 1 ? 1.0 : n * factorial(n - 1);
}

MaterialOptions steel_3d(MaterialModel model = MaterialModel::saint_venant_kirchhoff) {
  return {2.0e11, 0.3, 7800.0, PlaneModel::plane_strain, model};
}

Vec30 displacement_of(const TetNodes& X, const Mat3& F, const Vec3& c) {
  Vec30 u;
  for (std::size_t k = 0; k < 10; ++k)
    u.segment<3>(3 * static_cast<Eigen::Index>(k)) = (F - Mat3::Identity()) * X[k] + c;
  return u;
}

} // namespace

TEST_CASE("T10: shape functions: partition of unity, Kronecker at the nodes, derivatives",
          "[structure_fem][t10]") {
  for (std::size_t k = 0; k < 10; ++k) {
    const auto& p = t10_node_parent[k];
    const auto N = t10_shape(p[0], p[1], p[2]);
    for (std::size_t j = 0; j < 10; ++j)
      CHECK_THAT(N(static_cast<Eigen::Index>(j)), WithinAbs(j == k ? 1.0 : 0.0, 1e-15));
  }
  for (std::size_t e = 0; e < 6; ++e) { // edge node 4 + e is the midpoint of its edge
    const auto& m = t10_node_parent[4 + e];
    const auto& a = t10_node_parent[static_cast<std::size_t>(t10_edges[e][0])];
    const auto& b = t10_node_parent[static_cast<std::size_t>(t10_edges[e][1])];
    for (int i = 0; i < 3; ++i) CHECK(m[i] == 0.5 * (a[i] + b[i]));
  }
  const double h = 1e-6;
  for (const auto& q : tet_rule_degree5) {
    CHECK_THAT(t10_shape(q.xi, q.eta, q.zeta).sum(), WithinAbs(1.0, 1e-14));
    const auto dN = t10_shape_derivatives(q.xi, q.eta, q.zeta);
    CHECK(dN.rowwise().sum().cwiseAbs().maxCoeff() < 1e-13);
    const auto fd = [&](double dx, double dy, double dz) -> Eigen::Matrix<double, 10, 1> {
      return (t10_shape(q.xi + dx, q.eta + dy, q.zeta + dz) -
              t10_shape(q.xi - dx, q.eta - dy, q.zeta - dz)) /
             (2.0 * h);
    };
    CHECK((dN.row(0).transpose() - fd(h, 0, 0)).cwiseAbs().maxCoeff() < 1e-8);
    CHECK((dN.row(1).transpose() - fd(0, h, 0)).cwiseAbs().maxCoeff() < 1e-8);
    CHECK((dN.row(2).transpose() - fd(0, 0, h)).cwiseAbs().maxCoeff() < 1e-8);
  }
}

TEST_CASE("T10: the quadrature rules integrate every monomial of their degree exactly",
          "[structure_fem][t10]") {
  auto check = [](const auto& rule, int degree) {
    for (int i = 0; i <= degree; ++i)
      for (int j = 0; i + j <= degree; ++j)
        for (int k = 0; i + j + k <= degree; ++k) {
          double sum = 0.0;
          for (const auto& q : rule)
            sum += q.weight * std::pow(q.xi, i) * std::pow(q.eta, j) * std::pow(q.zeta, k);
          const double exact =
              factorial(i) * factorial(j) * factorial(k) / factorial(i + j + k + 3);
          CAPTURE(degree, i, j, k);
          CHECK_THAT(sum, WithinRel(exact, 1e-14));
        }
  };
  check(tet_rule_degree2, 2);
  check(tet_rule_degree5, 5);
}

TEST_CASE("T10: the volume of a curved tetrahedron equals its closed form",
          "[structure_fem][t10]") {
  CHECK_THAT(t10_volume(straight()), WithinRel(affine().determinant() / 6.0, 1e-14));
  CHECK_THAT(t10_volume(curved()), WithinRel(curved_volume(), 1e-14));
  CHECK(std::abs(curved_volume() / (affine().determinant() / 6.0) - 1.0) > 0.05); // really curved
}

TEST_CASE("T10: patch test: a homogeneous finite deformation gives the nodal forces of the "
          "boundary tractions P N",
          "[structure_fem][t10]") {
  // Each face of the straight element carries the uniform traction P N (N the outward reference
  // normal); its consistent nodal forces on a 6-node triangle are zero at the vertices and
  // t A / 3 at each edge node.
  constexpr std::array<std::array<int, 7>, 4> faces{{{0, 1, 2, 4, 5, 6, 3}, // vertices, edge
                                                     {0, 1, 3, 4, 9, 7, 2}, // nodes, and the
                                                     {0, 2, 3, 6, 8, 7, 1}, // opposite vertex
                                                     {1, 2, 3, 5, 8, 9, 0}}};
  const TetNodes X = straight();
  Mat3 F;
  F << 1.08, 0.21, -0.07, -0.12, 0.93, 0.15, 0.05, -0.18, 1.11; // stretch, shear, rotation
  for (const auto model : {MaterialModel::saint_venant_kirchhoff, MaterialModel::neo_hookean}) {
    CAPTURE(static_cast<int>(model));
    const auto law = make_material_3d(steel_3d(model));
    const Mat3 H = F - Mat3::Identity();
    const Mat3 P = F * law->stress(0.5 * (H + H.transpose() + H.transpose() * H));
    Vec30 expected = Vec30::Zero();
    for (const auto& face : faces) {
      const auto at = [&](int i) {
        return X[static_cast<std::size_t>(face[static_cast<std::size_t>(i)])];
      };
      Vec3 NA = 0.5 * (at(1) - at(0)).cross(at(2) - at(0)); // N times the face area
      if (NA.dot(at(0) - at(6)) < 0.0) NA = -NA;
      for (int m = 3; m < 6; ++m)
        expected.segment<3>(3 * face[static_cast<std::size_t>(m)]) += P * NA / 3.0;
    }
    Vec30 f;
    ElementT10(X).internal_force(displacement_of(X, F, Vec3(0.01, -0.02, 0.03)), *law, f, nullptr);
    CHECK((f - expected).cwiseAbs().maxCoeff() <= 1e-12 * expected.cwiseAbs().maxCoeff());
  }
}

TEST_CASE("T10: a rigid rotation of 60 degrees gives zero internal force", "[structure_fem][t10]") {
  const TetNodes X = curved();
  const Mat3 R = Eigen::AngleAxisd(std::numbers::pi / 3.0, Vec3(1.0, 2.0, -0.5).normalized())
                     .toRotationMatrix();
  for (const auto model : {MaterialModel::saint_venant_kirchhoff, MaterialModel::neo_hookean}) {
    CAPTURE(static_cast<int>(model));
    const auto law = make_material_3d(steel_3d(model));
    Vec30 f;
    const ElementT10 element(X);
    const double detF =
        element.internal_force(displacement_of(X, R, Vec3(1.0, -2.0, 0.5)), *law, f, nullptr);
    CHECK_THAT(detF, WithinRel(1.0, 1e-13));
    // Scale: the force of a unit strain, E V^(2/3).
    const double scale = steel_3d().youngs_modulus * std::cbrt(curved_volume() * curved_volume());
    CHECK(f.cwiseAbs().maxCoeff() <= 1e-12 * scale);
  }
}

TEST_CASE("T10: the tangent equals central differences of the internal force",
          "[structure_fem][t10]") {
  const TetNodes X = curved();
  const ElementT10 element(X);
  Vec30 u;
  for (int i = 0; i < 30; ++i) u(i) = 0.08 * std::sin(12.9898 * i + 78.233); // det F > 0
  for (const auto model : {MaterialModel::saint_venant_kirchhoff, MaterialModel::neo_hookean}) {
    CAPTURE(static_cast<int>(model));
    const auto law = make_material_3d(steel_3d(model));
    Vec30 f;
    Mat30 K;
    REQUIRE(element.internal_force(u, *law, f, &K) > 0.5);
    const double h = 1e-6, Kmax = K.cwiseAbs().maxCoeff();
    for (int j = 0; j < 30; ++j) {
      Vec30 fp, fm;
      Vec30 du = Vec30::Zero();
      du(j) = h;
      element.internal_force(u + du, *law, fp, nullptr);
      element.internal_force(u - du, *law, fm, nullptr);
      CHECK(((fp - fm) / (2.0 * h) - K.col(j)).cwiseAbs().maxCoeff() <= 1e-6 * Kmax);
    }
    CHECK((K - K.transpose()).cwiseAbs().maxCoeff() <= 1e-12 * Kmax);
  }
}

TEST_CASE("T10: consistent mass: rho V per direction, and the exact straight-sided matrix",
          "[structure_fem][t10]") {
  const double rho = 7800.0;
  const Mat30 Mc = t10_mass(curved(), rho);
  for (int k = 0; k < 3; ++k) {
    double sum = 0.0, cross = 0.0;
    for (int a = 0; a < 10; ++a)
      for (int b = 0; b < 10; ++b) {
        sum += Mc(3 * a + k, 3 * b + k);
        cross += std::abs(Mc(3 * a + k, 3 * b + (k + 1) % 3));
      }
    CHECK_THAT(sum, WithinRel(rho * curved_volume(), 1e-13));
    CHECK(cross == 0.0);
  }
  // Straight sides: M_ab = rho V m_ab / 420 with m = 6 (vertex diagonal), 1 (two vertices),
  // -4 (a vertex and an edge node on its edge), -6 (off its edge), 32 (edge diagonal),
  // 16 (two edges sharing a vertex), 8 (opposite edges).
  const double V = affine().determinant() / 6.0;
  const Mat30 M = t10_mass(straight(), rho);
  auto edge = [](int e) { return t10_edges[static_cast<std::size_t>(e - 4)]; };
  auto on_edge = [&](int v, int e) { return edge(e)[0] == v || edge(e)[1] == v; };
  auto share = [&](int e, int g) { return on_edge(edge(g)[0], e) || on_edge(edge(g)[1], e); };
  for (int a = 0; a < 10; ++a)
    for (int b = 0; b < 10; ++b) {
      double m;
      if (a < 4 && b < 4)
        m = a == b ? 6 : 1;
      else if (a < 4 || b < 4)
        m = on_edge(std::min(a, b), std::max(a, b)) ? -4 : -6;
      else
        m = a == b ? 32 : (share(a, b) ? 16 : 8);
      CAPTURE(a, b);
      CHECK_THAT(M(3 * a + 1, 3 * b + 1), WithinAbs(rho * V * m / 420.0, 1e-12 * rho * V));
    }
}
