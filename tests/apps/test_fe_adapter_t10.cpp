// The coupler's S on a T10 structure (fem_plugin::FeAdapterT10 over fem::interface_of): a pressure
// projected onto the interface as the fluid does it (point loads at face quadrature points,
// coupling::project_point_loads, eqs. 53-58) becomes FE nodal forces with the pressure's total
// force and no moment, and bends a clamped cantilever as structure_fem's own face-pressure load
// does; a rigid motion of the FE nodes is the interface motion (eqs. 60-62).
#include <catch2/catch.hpp>

#include <algorithm>
#include <functional>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include "coupling/projection.hpp"
#include "fem/fe_adapter.hpp"
#include "structure_fem/box_mesher.hpp"
#include "structure_fem/loads.hpp"
#include "structure_fem/shape_t6.hpp"

using fsi::Vec3;
using namespace fsi::fem;
using fsi::app::fem_plugin::FeAdapterT10;

namespace {

const BoxMeshOptions beam{{0.0, 0.0, 0.0}, {1.0, 0.1, 0.1}, {8, 1, 1}};

StructureT10Options clamped_at_x_min() {
  StructureT10Options o;
  o.material = {1.0e6, 0.3, 1000.0};
  o.newton.residual_rtol = 1e-12;
  o.clamped = {{"x_min", {true, true, true}, {}, {}}};
  return o;
}

/// The loads a fluid would hand over for the pressure p(X) [Pa] on the interface: the point
/// load -p N dA at each point of the degree-4 rule of each face (N dA = dX/dxi x dX/deta dxi
/// deta, out of the solid), projected with the face shape functions (eq. 58).
fsi::coupling::InterfaceLoads3
face_rule_pressure_loads(const FeInterface3& fi, const std::function<double(const Vec3&)>& p) {
  std::vector<fsi::coupling::PointLoad3> points;
  const auto& X = fi.mesh.X0;
  for (std::size_t f = 0; f < fi.mesh.faces.size(); ++f)
    for (const auto& q : rule_degree4) {
      const auto dN = t6_shape_derivatives(q.xi, q.eta);
      Vec3 dX_dxi = Vec3::Zero(), dX_deta = Vec3::Zero();
      for (std::size_t k = 0; k < 6; ++k) {
        dX_dxi += dN(0, static_cast<Eigen::Index>(k)) * X[fi.mesh.faces[f][k]];
        dX_deta += dN(1, static_cast<Eigen::Index>(k)) * X[fi.mesh.faces[f][k]];
      }
      const Vec3 x = fsi::face_point(fi.mesh, X, f, q.xi, q.eta);
      points.push_back({f, q.xi, q.eta, -p(x) * q.weight * dX_dxi.cross(dX_deta)});
    }
  auto loads = fsi::coupling::InterfaceLoads3::zeros(fi.mesh.node_count());
  fsi::coupling::project_point_loads(fi.mesh, points, loads);
  return loads;
}

/// Largest |a_K - b_K| over the nodes of two node arrays, and the largest |a_K|.
std::pair<double, double> largest_difference(const Vector& a, const Vector& b) {
  double difference = 0.0, size = 0.0;
  for (Eigen::Index K = 0; K < a.size() / 3; ++K) {
    difference = std::max(difference, (a.segment<3>(3 * K) - b.segment<3>(3 * K)).norm());
    size = std::max(size, a.segment<3>(3 * K).norm());
  }
  return {difference, size};
}

} // namespace

TEST_CASE("FE adapter T10: a uniform pressure gives its force and no moment",
          "[apps][fem][adapter][3d]") {
  StructureT10Options free = clamped_at_x_min();
  free.clamped.clear(); // the structure keeps no force on a clamped dof (a reaction)
  StructureT10 structure(make_box_mesh(beam), free);
  const FeInterface3 fi = interface_of(structure.mesh(), {"z_max"});
  FeAdapterT10 adapter(structure, fi);
  const double p = 2.5e3, area = 1.0 * 0.1;
  adapter.set_interface_loads(face_rule_pressure_loads(fi, [p](const Vec3&) { return p; }));
  const Vector& f = structure.external_forces();
  const Vec3 centre(0.5, 0.05, 0.1); // of the face z = 0.1
  Vec3 force = Vec3::Zero(), moment = Vec3::Zero();
  for (std::size_t K = 0; K < structure.num_nodes(); ++K) {
    const Vec3 f_K = f.segment<3>(3 * static_cast<Eigen::Index>(K));
    force += f_K;
    moment += (structure.mesh().X[K] - centre).cross(f_K);
  }
  const Vec3 expected = -p * area * Vec3::UnitZ(); // against the outward normal
  const double force_error = (force - expected).norm() / (p * area);
  const double moment_error = moment.norm() / (p * area * 1.0);
  WARN("uniform pressure through the T10 adapter: |sum f - p A n| / pA = "
       << force_error << ", |moment about the face centre| / (pA L) = " << moment_error);
  CHECK(force_error <= 1e-12);
  CHECK(moment_error <= 1e-12);
}

TEST_CASE("FE adapter T10: a cantilever loaded through the adapter bends as under its own load",
          "[apps][fem][adapter][3d]") {
  const auto p = [](const Vec3& X) { return 1.0e2 * (1.0 + X.x()); }; // [Pa], growing to the tip
  StructureT10 own(make_box_mesh(beam), clamped_at_x_min());
  own.set_external_forces(face_pressure_forces(own.mesh(), "z_max", p));
  own.solve_static();

  StructureT10 coupled(make_box_mesh(beam), clamped_at_x_min());
  const FeInterface3 fi = interface_of(coupled.mesh(), {"z_max"});
  FeAdapterT10 adapter(coupled, fi);
  adapter.set_interface_loads(face_rule_pressure_loads(fi, p));
  const auto [force_difference, force] =
      largest_difference(coupled.external_forces(), own.external_forces());
  coupled.solve_static();
  const auto [difference, deflection] =
      largest_difference(coupled.displacement(), own.displacement());
  WARN("T10 cantilever: largest nodal force difference "
       << force_difference / force << " of the largest force; deflection " << deflection
       << " m, largest displacement difference " << difference / deflection << " of it");
  CHECK(deflection > 1e-3); // bent visibly
  CHECK(force_difference <= 1e-14 * force);
  CHECK(difference <= 1e-12 * deflection);
}

TEST_CASE("FE adapter T10: a rigid motion of the FE nodes is the interface motion",
          "[apps][fem][adapter][3d]") {
  StructureT10 structure(make_box_mesh(beam), clamped_at_x_min());
  const FeInterface3 fi = interface_of(structure.mesh(), {"x_max", "y_min", "z_max"});
  FeAdapterT10 adapter(structure, fi);
  // x = p + R (X - p) + c, v = omega x (x - p - c) + c_dot, a = omega x (omega x (x - p - c)).
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.3, Vec3(1.0, 2.0, 3.0).normalized()).matrix();
  const Vec3 p(0.2, 0.05, -0.1), c(0.01, -0.02, 0.03), c_dot(1.0, 2.0, 3.0);
  const Vec3 omega(0.1, -0.2, 0.3);
  const auto x = [&](const Vec3& X) { return Vec3(p + R * (X - p) + c); };
  const auto v = [&](const Vec3& X) { return Vec3(omega.cross(R * (X - p)) + c_dot); };
  const auto a = [&](const Vec3& X) { return Vec3(omega.cross(omega.cross(R * (X - p)))); };
  StructureState rigid = structure.save();
  for (std::size_t K = 0; K < structure.num_nodes(); ++K) {
    const Vec3& X = structure.mesh().X[K];
    const auto d = 3 * static_cast<Eigen::Index>(K);
    rigid.u.segment<3>(d) = x(X) - X;
    rigid.v.segment<3>(d) = v(X);
    rigid.a.segment<3>(d) = a(X);
  }
  structure.restore(rigid);
  const fsi::coupling::InterfaceMotion3 m = adapter.interface_motion();
  REQUIRE(m.size() == fi.mesh.node_count());
  double x_error = 0.0, va_error = 0.0;
  for (std::size_t k = 0; k < m.size(); ++k) {
    const Vec3& X = fi.mesh.X0[k];
    x_error = std::max(x_error, (m.x[k] - x(X)).norm());
    va_error = std::max({va_error, (m.v[k] - v(X)).norm(), (m.a[k] - a(X)).norm()});
  }
  WARN("rigid rotation and translation through the T10 adapter: largest position error "
       << x_error << " m, velocity and acceleration " << va_error);
  CHECK(x_error <= 1e-15);
  CHECK(va_error == 0.0);
}

TEST_CASE("FE adapter T10: a body falling with its clamp moves rigidly, step by step",
          "[apps][fem][adapter][3d]") {
  const Vec3 g(0.5, 0.0, -9.81); // gravity and the clamp's acceleration [m/s^2]
  StructureT10Options o = clamped_at_x_min();
  o.gravity = g;
  o.newmark = {0.25, 0.5};
  o.clamped[0].motion = [&](const Vec3&, double t) {
    return PrescribedKinematics3{0.5 * t * t * g, t * g, g};
  };
  StructureT10 structure(make_box_mesh(beam), o);
  const FeInterface3 fi = interface_of(structure.mesh(), {"x_max", "z_min"});
  FeAdapterT10 adapter(structure, fi);
  const auto no_loads = fsi::coupling::InterfaceLoads3::zeros(fi.mesh.node_count());
  const double dt = 0.01;
  for (int n = 0; n < 10; ++n) {
    adapter.set_interface_loads(no_loads);
    adapter.advance(n * dt, dt);
  }
  adapter.save_state();
  const auto run = [&] {
    for (int n = 10; n < 20; ++n) {
      adapter.set_interface_loads(no_loads);
      adapter.advance(n * dt, dt);
    }
    return adapter.interface_motion();
  };
  const fsi::coupling::InterfaceMotion3 first = run();
  adapter.restore_state();
  const fsi::coupling::InterfaceMotion3 again = run();
  const double t = structure.time();
  double deviation = 0.0;
  for (std::size_t k = 0; k < first.size(); ++k) {
    deviation = std::max(deviation, (first.x[k] - fi.mesh.X0[k] - 0.5 * t * t * g).norm());
    CHECK(again.x[k] == first.x[k]); // restored to the saved state exactly
    CHECK(again.v[k] == first.v[k]);
    CHECK((first.v[k] - t * g).norm() <= 1e-10 * t * g.norm());
  }
  WARN("T10 body falling with its clamp for " << t << " s through the adapter: largest "
                                              << "interface deviation from the rigid motion "
                                              << deviation << " m");
  CHECK(deviation <= 1e-10 * 0.5 * t * t * g.norm());
}
