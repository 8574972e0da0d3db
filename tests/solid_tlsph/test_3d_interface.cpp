// The 3-D TL-SPH solid's coupling interface (interface_box.cpp): order-1 triangles over the box's
// faces that close the surface with the right orientation, nodes that follow an affine motion
// exactly, and loads that reach the particles whole (the total force on the solid equals the
// total load on the mesh to round-off).
#include <catch2/catch.hpp>

#include <Eigen/Geometry>
#include <cmath>
#include <random>
#include <vector>

#include "fsi/core/error.hpp"
#include "solid_tlsph/solid.hpp"

namespace {

using fsi::Mat3;
using fsi::Vec3;
using namespace fsi::tlsph;

constexpr double a = 0.06, b = 0.05, c = 0.04;

/// A free a x b x c block at dp = 0.01, no gravity, its interface on the faces `tags` (all: {}).
TlsphSolid3 interface_block(std::vector<std::string> tags) {
  TlsphOptions3 o;
  o.dp = 0.01;
  o.material = {1.0e6, 0.3, 1000.0, fsi::materials::PlaneModel::plane_strain};
  o.gravity = Vec3::Zero();
  o.interface_tags = std::move(tags);
  return TlsphSolid3(fill_box(Vec3::Zero(), Vec3(a, b, c), o.dp), o);
}

/// Area vector (x1 - x0) x (x2 - x0) / 2 of face f at node positions x.
Vec3 area(const fsi::InterfaceMesh3& m, const std::vector<Vec3>& x, std::size_t f) {
  const auto& k = m.faces[f];
  return 0.5 * (x[k[1]] - x[k[0]]).cross(x[k[2]] - x[k[0]]);
}

} // namespace

TEST_CASE("tlsph 3-D: the interface closes the box's surface, oriented outwards",
          "[solid_tlsph][3d][interface]") {
  const TlsphSolid3 s = interface_block({});
  const fsi::InterfaceMesh3 m = s.interface_mesh();
  REQUIRE(m.order == 1);
  // Per face (ni + 2) x (nj + 2) nodes; the box's edges and corners shared.
  CHECK(m.node_count() == 8 * 7 * 6 - 6 * 5 * 4);
  Vec3 closure = Vec3::Zero();
  double total = 0.0, volume = 0.0;
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    const Vec3 A = area(m, m.X0, f);
    closure += A;
    total += A.norm();
    volume += m.X0[m.faces[f][0]].dot(A) / 3.0; // divergence theorem: sum x . n dA / 3
  }
  CHECK(closure.norm() < 1e-15);
  CHECK(total == Approx(2.0 * (a * b + b * c + c * a)).epsilon(1e-13));
  CHECK(volume == Approx(a * b * c).epsilon(1e-13));
  for (std::size_t k = 0; k < m.node_count(); ++k) // each node over its particle, dp/2 deep
    CHECK((s.reference_position(s.interface_particles()[k]) - m.X0[k]).norm() <
          std::sqrt(3.0) * 0.005 + 1e-12);
  // One tagged face: its area, its outward normal.
  const TlsphSolid3 top = interface_block({"z+"});
  const fsi::InterfaceMesh3 t = top.interface_mesh();
  Vec3 sum = Vec3::Zero();
  for (std::size_t f = 0; f < t.faces.size(); ++f) sum += area(t, t.X0, f);
  CHECK((sum - Vec3(0.0, 0.0, a * b)).norm() < 1e-15);
}

TEST_CASE("tlsph 3-D: interface nodes and normals follow an affine motion exactly",
          "[solid_tlsph][3d][interface]") {
  TlsphSolid3 s = interface_block({});
  const std::vector<Vec3> n0 = s.interface_normals(); // F = I: the reference normals
  const Mat3 A =
      (Mat3() << 1.02, 0.013, -0.007, -0.011, 0.985, 0.021, 0.004, -0.016, 1.01).finished();
  const Vec3 d(0.3, -0.2, 0.1);
  std::vector<Vec3> x(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) x[i] = A * s.reference_position(i) + d;
  s.set_positions(x);
  const fsi::InterfaceMesh3 m = s.interface_mesh();
  const std::vector<Vec3> xn = s.interface_positions(), n = s.interface_normals();
  double err = 0.0, err_n = 0.0;
  for (std::size_t k = 0; k < m.node_count(); ++k)
    err = std::max(err, (xn[k] - (A * m.X0[k] + d)).norm());
  // A node inside a face (its reference normal the face's): Nanson's normal is the deformed
  // triangle's.
  std::size_t inside = 0;
  for (std::size_t f = 0; f < m.faces.size(); ++f)
    for (int j = 0; j < 3; ++j) {
      const std::size_t k = m.faces[f][static_cast<std::size_t>(j)];
      if ((n0[k] - area(m, m.X0, f).normalized()).norm() > 1e-14) continue;
      err_n = std::max(err_n, (n[k] - area(m, xn, f).normalized()).norm());
      ++inside;
    }
  CHECK(inside > m.faces.size());
  CHECK(err < 1e-13);
  CHECK(err_n < 1e-13);
}

TEST_CASE("tlsph 3-D: the total force on the solid equals the total interface load",
          "[solid_tlsph][3d][interface]") {
  TlsphSolid3 s = interface_block({});
  const std::size_t nodes = s.interface_mesh().node_count();
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> f(nodes);
  Vec3 load = Vec3::Zero();
  for (auto& q : f) q = Vec3(u(rng), u(rng), u(rng)), load += q;
  s.set_interface_loads(f);
  // At rest the internal forces vanish; sum m a is the external force (eq. 12).
  Vec3 force = Vec3::Zero();
  for (std::size_t i = 0; i < s.size(); ++i)
    force += s.options().material.density * s.volume(i) * s.acceleration(i);
  INFO("total load " << load.transpose() << " N, sum m a " << force.transpose() << " N");
  CHECK((force - load).norm() < 1e-12 * static_cast<double>(f.size()));
  CHECK_THROWS_AS(s.set_interface_loads(std::vector<Vec3>(nodes - 1)), fsi::InputError);
}
