#include "geometry_erp/interface_triangles.hpp"

#include "fsi/core/error.hpp"

#include <string>

namespace fsi::erp {

namespace {

// The parent points of a 6-node face's slots: corners (0, 0), (1, 0), (0, 1), then the mid-sides.
constexpr std::array<ParentPoint<3>, 6> kSlot{
    {{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}, {0.5, 0.0}, {0.5, 0.5}, {0.0, 0.5}}};

// The flat triangles of a face, as slots, each counter-clockwise in (xi, eta) like the face.
constexpr std::array<std::array<int, 3>, 4> kQuadratic{
    {{0, 3, 5}, {3, 1, 4}, {5, 4, 2}, {3, 4, 5}}};
constexpr std::array<int, 3> kLinear{0, 1, 2};

} // namespace

InterfaceTriangles::InterfaceTriangles(TriangleWallSet& walls, const InterfaceMesh3& mesh,
                                       int group)
    : mesh_(mesh) {
  if (mesh.order != 1 && mesh.order != 2)
    throw InputError("interface: faces of order " + std::to_string(mesh.order) +
                     " (1 or 2 expected)");
  std::vector<std::array<int, 3>> triangles;
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    for (const std::size_t k : mesh.faces[f])
      if (k >= mesh.node_count())
        throw InputError("interface: node " + std::to_string(k) + " is not on the interface (" +
                         std::to_string(mesh.node_count()) + " nodes)");
    const auto add = [&](const std::array<int, 3>& slots) {
      std::array<int, 3> nodes{};
      for (std::size_t j = 0; j < 3; ++j)
        nodes[j] = static_cast<int>(mesh.faces[f][static_cast<std::size_t>(slots[j])]);
      triangles.push_back(nodes);
      face_of_.push_back(static_cast<int>(f));
      sub_vertex_.push_back(slots);
    };
    if (mesh.order == 2)
      for (const auto& slots : kQuadratic) add(slots);
    else
      add(kLinear);
  }
  range_ = walls.add_triangles(mesh.X0, triangles, group);
}

ParentPoint<3> InterfaceTriangles::parent_point(int triangle, double s, double t) const {
  const auto& [a, b, c] = sub_vertex_[local(triangle)];
  const auto& pa = kSlot[static_cast<std::size_t>(a)];
  const auto& pb = kSlot[static_cast<std::size_t>(b)];
  const auto& pc = kSlot[static_cast<std::size_t>(c)];
  return {pa[0] + s * (pb[0] - pa[0]) + t * (pc[0] - pa[0]),
          pa[1] + s * (pb[1] - pa[1]) + t * (pc[1] - pa[1])};
}

InterfaceTriangles::LoadWeights InterfaceTriangles::load_weights(int triangle, double s,
                                                                 double t) const {
  const ParentPoint<3> p = parent_point(triangle, s, t);
  return {mesh_.faces[static_cast<std::size_t>(face(triangle))],
          face_shape_functions(mesh_.order, p[0], p[1])};
}

} // namespace fsi::erp
