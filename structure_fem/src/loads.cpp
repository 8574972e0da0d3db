#include "structure_fem/loads.hpp"

#include <cmath>

#include "structure_fem/shape_t6.hpp"

namespace fsi::fem {

Vector edge_traction_forces(const Mesh& mesh, const std::string& tag, const Vec2& traction) {
  return edge_traction_field_forces(mesh, tag, [&](const Vec2&) { return traction; });
}

Vector edge_traction_field_forces(const Mesh& mesh, const std::string& tag,
                                  const std::function<Vec2(const Vec2& X)>& traction) {
  Vector f = Vector::Zero(2 * static_cast<Eigen::Index>(mesh.num_nodes()));
  const double s_q[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)};
  const double w_q[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  for (const auto& edge : mesh.edges_with_tag(tag))
    for (int q = 0; q < 3; ++q) {
      const Eigen::Vector3d N = edge3_shape(s_q[q]), dN = edge3_shape_derivative(s_q[q]);
      Vec2 X = Vec2::Zero(), dXds = Vec2::Zero();
      for (std::size_t k = 0; k < 3; ++k) {
        X += N[static_cast<Eigen::Index>(k)] * mesh.X[static_cast<std::size_t>(edge.nodes[k])];
        dXds += dN[static_cast<Eigen::Index>(k)] * mesh.X[static_cast<std::size_t>(edge.nodes[k])];
      }
      const Vec2 t = traction(X) * (w_q[q] * dXds.norm());
      for (std::size_t k = 0; k < 3; ++k)
        f.segment<2>(2 * edge.nodes[k]) += N[static_cast<Eigen::Index>(k)] * t;
    }
  return f;
}

} // namespace fsi::fem
