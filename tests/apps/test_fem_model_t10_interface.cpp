// The T10 structure's interface through the fem plug-in (FemModelT10: the tagged surface's 6-node
// faces, fem::interface_of, and S on them): a uniform pressure handed over as a 3-D fluid does,
// point loads on the four flat triangles of each face (erp::InterfaceTriangles) shared among the
// face's nodes by its shape functions (eq. 58), gives structure_fem's consistent pressure load to
// round-off, sums to p A, and bends a clamped plate as the scene's own pressure load does.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "fem/fem_model_t10.hpp"
#include "fsi_app/scene.hpp"
#include "geometry_erp/interface_triangles.hpp"
#include "structure_fem/loads.hpp"

using fsi::Vec3;
using namespace fsi::app;

namespace {

// A 1 m x 1 m x 0.05 m plate of 4 x 4 x 1 cells (96 T10), clamped on its four edges' faces,
// wetted on its face z = 0.05 (front).
const std::string plate_scene = R"(dimension: 3
gravity: [0.0, 0.0, 0.0]
time: {end: 0.002, dt: 0.001}
output: {interval: 0.001}
structures:
  - name: plate
    mesh: {kind: box, origin: [0, 0, 0], width: 1.0, height: 1.0, depth: 0.05,
           elements_x: 4, elements_y: 4, elements_z: 1}
    material: {youngs_modulus: 1.0e7, poisson_ratio: 0.3, density: 1000.0}
    clamped: [left, right, bottom, top]
    interface: [front]
)";

std::unique_ptr<StructurePart> build(const std::string& text) {
  return find_structure_plugin("fem")->build(parse_scene(text, "p.yaml", {}), 0);
}

/// The loads of a pressure p on the interface as the 3-D EMPS fluid hands them over: on each flat
/// triangle the force -p n A at the three points of the degree-2 rule (A/3 each, exact for the
/// face's quadratic shape functions on the triangle), shared by InterfaceTriangles::load_weights.
fsi::coupling::InterfaceLoads3 triangle_wall_pressure_loads(const fsi::InterfaceMesh3& mesh,
                                                            double p) {
  fsi::erp::TriangleWallSet walls;
  const fsi::erp::InterfaceTriangles wet(walls, mesh, 0);
  walls.update();
  auto loads = fsi::coupling::InterfaceLoads3::zeros(mesh.node_count());
  const std::array<std::array<double, 2>, 3> points{
      {{1.0 / 6, 1.0 / 6}, {2.0 / 3, 1.0 / 6}, {1.0 / 6, 2.0 / 3}}};
  for (int t = wet.first_triangle(); t < wet.first_triangle() + wet.triangle_count(); ++t) {
    const auto& v = walls.triangles().node[static_cast<std::size_t>(t)];
    const auto x = [&](int j) { return walls.nodes().x[static_cast<std::size_t>(v[j])]; };
    const double area = 0.5 * (x(1) - x(0)).cross(x(2) - x(0)).norm();
    const Vec3 f = -p * area / 3.0 * walls.face_normal(t);
    for (const auto& q : points) {
      const auto w = wet.load_weights(t, q[0], q[1]);
      for (std::size_t j = 0; j < w.k.size(); ++j) loads.f[w.k[j]] += w.N[j] * f;
    }
  }
  return loads;
}

} // namespace

TEST_CASE("FemModelT10: a pressure through the interface's flat triangles is the consistent "
          "load, sums to p A and bends the plate as the scene's pressure does",
          "[apps][fem][3d]") {
  const double p = 100.0, area = 1.0;
  auto coupled_part = build(plate_scene);
  auto& coupled = dynamic_cast<fem_plugin::FemModelT10&>(*coupled_part);
  const fsi::fem::FeInterface3& fi = coupled.interface();
  REQUIRE(fi.mesh.faces.size() == 2 * 4 * 4);
  const auto loads = triangle_wall_pressure_loads(fi.mesh, p);
  Vec3 sum = Vec3::Zero();
  for (const Vec3& f : loads.f) sum += f;
  coupled.coupling_solver3().set_interface_loads(loads);
  // structure_fem's own consistent load of the same pressure on the same face
  const fsi::fem::Vector own = fsi::fem::face_pressure_forces(coupled.structure().mesh(), "front",
                                                              [p](const Vec3&) { return p; });
  // On the free dofs: the clamped rim's nodes carry reactions (the interface hands them none,
  // face_pressure_forces its share; neither moves the plate).
  double load_difference = 0.0;
  const fsi::fem::DofMap& dofs = coupled.structure().dofs();
  for (int d = 0; d < dofs.num_dofs(); ++d)
    if (dofs.free_index(d) >= 0)
      load_difference =
          std::max(load_difference,
                   std::abs(coupled.structure().external_forces()[d] - own[d]) / (p * area));
  coupled.structure().solve_static();

  auto scene_part = build(plate_scene + "    loads: [{boundary: front, pressure: 100.0}]\n");
  auto& loaded = dynamic_cast<fem_plugin::FemModelT10&>(*scene_part);
  loaded.structure().solve_static();
  const fsi::fem::Vector& u = coupled.structure().displacement();
  const double w_max = u.cwiseAbs().maxCoeff();
  const double u_difference = (u - loaded.structure().displacement()).cwiseAbs().maxCoeff();
  WARN("T10 plate: |sum f - (-p A e_z)| / pA = "
       << (sum + p * area * Vec3::UnitZ()).norm() / (p * area)
       << ", largest nodal difference to the consistent load / pA " << load_difference
       << "; largest deflection " << w_max << " m, difference to the scene's pressure load "
       << u_difference / w_max << " of it");
  CHECK((sum + p * area * Vec3::UnitZ()).norm() <= 1e-13 * p * area);
  CHECK(load_difference <= 1e-14);
  CHECK(w_max > 1e-4);
  CHECK(u_difference <= 1e-10 * w_max);
}
