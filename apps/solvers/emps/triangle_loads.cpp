#include "emps/triangle_loads.hpp"

#include <algorithm>

namespace fsi::app::emps_plugin {

void project_triangle_forces(const emps::WallForces3& forces, const erp::InterfaceTriangles& walls,
                             coupling::InterfaceLoads3& loads) {
  loads.f.assign(static_cast<std::size_t>(walls.node_count()), Vec3::Zero()); // keeps capacity
  const int first = walls.first_triangle(), last = first + walls.triangle_count();
  for (const emps::TriangleForces& face : forces)
    for (std::size_t i = 0; i < face.triangle.size(); ++i) {
      const int t = face.triangle[i];
      if (t < first || t >= last) continue;
      // x_wall = bary[0] x_a + bary[1] x_b + bary[2] x_c: local coordinates (s, t) = bary[1, 2]
      const erp::InterfaceTriangles::LoadWeights w =
          walls.load_weights(t, face.bary[i][1], face.bary[i][2]);
      for (std::size_t j = 0; j < w.k.size(); ++j) loads.f[w.k[j]] -= w.N[j] * face.f[i]; // eq. 59
    }
}

} // namespace fsi::app::emps_plugin
