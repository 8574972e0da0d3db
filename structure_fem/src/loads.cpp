#include "structure_fem/loads.hpp"

#include <cmath>

#include <Eigen/Geometry>

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

namespace {

/// f_K = integral_face N_K load(X, N dA / dxi deta) dxi deta over the faces tagged `tag`, where
/// N dA = dX/dxi x dX/deta dxi deta is the outward area vector (BoundaryFace orientation).
template <class Load> Vector face_forces(const TetMesh& mesh, const std::string& tag, Load&& load) {
  Vector f = Vector::Zero(3 * static_cast<Eigen::Index>(mesh.num_nodes()));
  for (const auto& face : mesh.faces_with_tag(tag))
    for (const auto& q : rule_degree4) {
      const auto N = t6_shape(q.xi, q.eta);
      const auto dN = t6_shape_derivatives(q.xi, q.eta);
      Vec3 X = Vec3::Zero(), dX_dxi = Vec3::Zero(), dX_deta = Vec3::Zero();
      for (std::size_t k = 0; k < 6; ++k) {
        const Vec3& X_k = mesh.X[static_cast<std::size_t>(face.nodes[k])];
        const auto K = static_cast<Eigen::Index>(k);
        X += N[K] * X_k;
        dX_dxi += dN(0, K) * X_k;
        dX_deta += dN(1, K) * X_k;
      }
      const Vec3 t = q.weight * load(X, Vec3(dX_dxi.cross(dX_deta)));
      for (std::size_t k = 0; k < 6; ++k)
        f.segment<3>(3 * face.nodes[k]) += N[static_cast<Eigen::Index>(k)] * t;
    }
  return f;
}

} // namespace

Vector face_traction_forces(const TetMesh& mesh, const std::string& tag,
                            const std::function<Vec3(const Vec3& X)>& traction) {
  return face_forces(
      mesh, tag, [&](const Vec3& X, const Vec3& n_dA) { return Vec3(traction(X) * n_dA.norm()); });
}

Vector face_pressure_forces(const TetMesh& mesh, const std::string& tag,
                            const std::function<double(const Vec3& X)>& pressure) {
  return face_forces(mesh, tag,
                     [&](const Vec3& X, const Vec3& n_dA) { return Vec3(-pressure(X) * n_dA); });
}

} // namespace fsi::fem
