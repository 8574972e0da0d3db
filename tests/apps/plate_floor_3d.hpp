#pragma once
// The 3-D coupled fluid tests' shared pieces (SPH: test_sph_coupled_3d.cpp, EMPS:
// test_emps_coupled_3d.cpp): a T10 plate forming a 0.4 x 0.4 m tank's floor, its interface at
// rest, and the restart check.
#include "coupling/interface.hpp"
#include "fsi/core/interface_mesh.hpp"
#include "fsi/core/state_archive.hpp"
#include "fsi_app/coupled_model.hpp"
#include "fsi_app/scene.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <string>

namespace fsi::test {

/// The scene's `structures` block: a 0.05 m aluminium plate of 2 x 1 x 2 cells (24 T10) under
/// y = 0 from x, z = 0, `width` m along x and 0.4 m along z, clamped on its four sides, wetted on
/// top.
inline std::string plate_floor_3d(const std::string& width = "0.4") {
  return R"(structures:
  - name: plate
    type: fem
    mesh: {kind: box, origin: [0.0, -0.05, 0.0], width: )" +
         width + R"(, height: 0.05, depth: 0.4,
           elements_x: 2, elements_y: 1, elements_z: 2}
    material: {youngs_modulus: 6.75e10, poisson_ratio: 0.34, density: 2700.0}
    clamped: [left, right, back, front]
    interface: [top]
)";
}

/// The interface nodes at their reference positions, at rest.
inline coupling::InterfaceMotion3 at_rest(const InterfaceMesh3& mesh) {
  coupling::InterfaceMotion3 m;
  m.x = mesh.X0;
  m.v.assign(mesh.node_count(), Vec3::Zero());
  m.a.assign(mesh.node_count(), Vec3::Zero());
  return m;
}

/// Four coupled steps of `scene` against two, a checkpoint into a new model and two more: the
/// interface motion and loads equal bit for bit, the plate sagged under the water;
/// same_fluid(whole, resumed) checks the fluid's particles.
template <class SameFluid>
void check_restart_bitwise(const app::Scene& scene, SameFluid&& same_fluid) {
  const double dt = *scene.time.dt;
  app::CoupledModel3 whole(scene), first(scene), second(scene);
  for (int k = 0; k < 4; ++k) whole.advance(k * dt, dt);
  for (int k = 0; k < 2; ++k) first.advance(k * dt, dt);
  StateArchive archive;
  first.write_state(archive);
  second.read_state(archive);
  for (int k = 2; k < 4; ++k) second.advance(k * dt, dt);
  same_fluid(whole, second);
  const auto& m = whole.scheme().interface_motion();
  const auto& n = second.scheme().interface_motion();
  CHECK(m.x == n.x);
  CHECK(m.v == n.v);
  CHECK(whole.scheme().interface_loads().f == second.scheme().interface_loads().f);
  const auto& X0 = whole.structure(0).interface_mesh3().X0;
  double sag = 0.0;
  for (std::size_t k = 0; k < m.size(); ++k) sag = std::min(sag, m.x[k].y() - X0[k].y());
  CHECK(sag < 0.0); // the plate has moved down under the water
}

} // namespace fsi::test
