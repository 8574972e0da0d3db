#include "fluid_sph/interface_boundary.hpp"

#include "fsi/core/error.hpp"

#include <algorithm>
#include <cmath>

namespace fsi::sph {

namespace {
double distance_to_chord(const InterfaceMesh& mesh, std::size_t e, const Vec2& q) {
  const Vec2 a = mesh.X0[mesh.edges[e][0]], ab = mesh.X0[mesh.edges[e][2]] - a;
  const double t = std::clamp((q - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (q - a - t * ab).norm();
}

// Unit normal into the fluid (right of a -> b: the solid is on the left) of edge e's chord.
Vec2 fluid_normal(const InterfaceMesh& mesh, const std::vector<Vec2>& x, std::size_t e) {
  const Vec2 t = (x[mesh.edges[e][2]] - x[mesh.edges[e][0]]).normalized();
  return {t.y(), -t.x()};
}
} // namespace

InterfaceBoundary::InterfaceBoundary(const InterfaceMesh& mesh, double dp, int layers)
    : mesh_(mesh) {
  if (mesh.edges.empty()) throw InputError("fluid_sph: the interface mesh has no edge");
  if (layers < 1) throw InputError("fluid_sph: interface layers " + std::to_string(layers));
  for (std::size_t e = 0; e < mesh.edges.size(); ++e) {
    const double length = (mesh.X0[mesh.edges[e][2]] - mesh.X0[mesh.edges[e][0]]).norm();
    const int n = std::max(1, static_cast<int>(std::ceil(length / dp - 1e-9)));
    for (int k = 0; k < layers; ++k)
      for (int q = 0; q < n; ++q) {
        edge_.push_back(e);
        xi_.push_back(-1.0 + (2.0 * q + 1.0) / n);
        depth_.push_back((k + 0.5) * dp);
      }
  }
  // A point nearer to another edge than to its own (behind a convex corner, or through a
  // structure thinner than the layers) would face the wrong fluid: dropped.
  std::vector<Vec2> x, normal;
  place(mesh.X0, x, normal);
  std::size_t kept = 0;
  for (std::size_t p = 0; p < size(); ++p) {
    const double own = distance_to_chord(mesh, edge_[p], x[p]) * (1.0 - 1e-9);
    bool nearest = true;
    for (std::size_t e = 0; e < mesh.edges.size() && nearest; ++e)
      nearest = e == edge_[p] || distance_to_chord(mesh, e, x[p]) >= own;
    if (!nearest) continue;
    edge_[kept] = edge_[p], xi_[kept] = xi_[p], depth_[kept] = depth_[p];
    ++kept;
  }
  edge_.resize(kept), xi_.resize(kept), depth_.resize(kept);
}

std::vector<WallPoint> InterfaceBoundary::wall_points(int group) const {
  std::vector<Vec2> x, n;
  place(mesh_.X0, x, n);
  std::vector<WallPoint> out(size());
  for (std::size_t p = 0; p < size(); ++p) out[p] = {x[p], n[p], group};
  return out;
}

void InterfaceBoundary::place(const std::vector<Vec2>& x, std::vector<Vec2>& position,
                              std::vector<Vec2>& normal) const {
  position.resize(size());
  normal.resize(size());
  for (std::size_t p = 0; p < size(); ++p) {
    normal[p] = fluid_normal(mesh_, x, edge_[p]);
    position[p] = edge_point(mesh_, x, edge_[p], xi_[p]) - depth_[p] * normal[p];
  }
}

void InterfaceBoundary::interpolate(const std::vector<Vec2>& nodal,
                                    std::vector<Vec2>& at_points) const {
  at_points.resize(size());
  for (std::size_t p = 0; p < size(); ++p)
    at_points[p] = edge_point(mesh_, nodal, edge_[p], xi_[p]);
}

void InterfaceBoundary::distribute(const std::vector<Vec2>& point_force,
                                   std::vector<Vec2>& nodal) const {
  nodal.assign(mesh_.node_count(), Vec2::Zero());
  for (std::size_t p = 0; p < size(); ++p) {
    const auto N = edge_shape_functions(mesh_.order, xi_[p]);
    const auto& k = mesh_.edges[edge_[p]];
    for (int j = 0; j < 3; ++j) nodal[k[j]] += N[j] * point_force[p];
  }
}

} // namespace fsi::sph
