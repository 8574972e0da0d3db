#pragma once
// The 3-D coupled fluid tests' shared pieces (SPH: test_sph_coupled_3d.cpp, EMPS:
// test_emps_coupled_3d.cpp): a T10 plate forming a 0.4 x 0.4 m tank's floor, and its interface
// at rest.
#include "coupling/interface.hpp"
#include "fsi/core/interface_mesh.hpp"

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

} // namespace fsi::test
