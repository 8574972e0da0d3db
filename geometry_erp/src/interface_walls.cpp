#include "geometry_erp/interface_walls.hpp"

#include "fsi/core/error.hpp"

#include <string>

namespace fsi::erp {

InterfaceWalls::InterfaceWalls(WallSet& walls, const InterfaceMesh& mesh, int group)
    : mesh_(mesh), first_node_(static_cast<int>(walls.nodes().size())),
      first_segment_(static_cast<int>(walls.segments().size())),
      node_count_(static_cast<int>(mesh.node_count())) {
  if (mesh.order != 1 && mesh.order != 2)
    throw InputError("interface: edges of order " + std::to_string(mesh.order) +
                     " (1 or 2 expected)");
  for (const Vec2& X : mesh.X0) walls.add_node(X);
  const auto L = [&](std::size_t k) {
    if (k >= mesh.node_count())
      throw InputError("interface: node " + std::to_string(k) + " is not on the interface (" +
                       std::to_string(mesh.node_count()) + " nodes)");
    return first_node_ + static_cast<int>(k);
  };
  for (std::size_t e = 0; e < mesh.edges.size(); ++e) {
    const auto [a, m, b] = mesh.edges[e];
    // Solid on the left of a -> b, so the fluid is on the left of b -> m -> a.
    if (mesh.order == 2) {
      walls.add_segment(L(b), L(m), group);
      edge_of_segment_.push_back(static_cast<int>(e));
      xi_.push_back({1.0, 0.0});
      walls.add_segment(L(m), L(a), group);
      edge_of_segment_.push_back(static_cast<int>(e));
      xi_.push_back({0.0, -1.0});
    } else {
      walls.add_segment(L(b), L(a), group);
      edge_of_segment_.push_back(static_cast<int>(e));
      xi_.push_back({1.0, -1.0});
    }
  }
}

double InterfaceWalls::parent_coordinate(int s, double t) const {
  const auto& [xi_a, xi_b] = xi_[static_cast<std::size_t>(s - first_segment_)];
  return xi_a + t * (xi_b - xi_a);
}

} // namespace fsi::erp
