#include "geometry_erp/fe_interface.hpp"

#include "fsi/core/error.hpp"

#include <cassert>
#include <string>

namespace fsi::erp {

FeInterface::FeInterface(WallSet& walls, std::span<const Vec2> X0,
                         std::span<const std::array<int, 3>> edges, int group)
    : first_node_(static_cast<int>(walls.nodes().size())),
      first_segment_(static_cast<int>(walls.segments().size())), ncr_inverse_(X0.size(), -1),
      edges_(edges.begin(), edges.end()) {
  const auto node_of = [&](int K) {
    if (K < 0 || static_cast<std::size_t>(K) >= X0.size())
      throw InputError("FE interface: node " + std::to_string(K) + " is not in the mesh (" +
                       std::to_string(X0.size()) + " nodes)");
    int& L = ncr_inverse_[static_cast<std::size_t>(K)];
    if (L < 0) {
      L = walls.add_node(X0[static_cast<std::size_t>(K)]);
      ncr_.push_back(K);
    }
    return L;
  };
  for (std::size_t e = 0; e < edges_.size(); ++e) {
    const auto [K0, Km, K1] = edges_[e];
    const int L0 = node_of(K0), Lm = node_of(Km), L1 = node_of(K1);
    // Solid on the left of K0 -> K1, so the fluid is on the left of K1 -> Km -> K0.
    walls.add_segment(L1, Lm, group);
    edge_of_segment_.push_back(static_cast<int>(e));
    xi_.push_back({1.0, 0.0});
    walls.add_segment(Lm, L0, group);
    edge_of_segment_.push_back(static_cast<int>(e));
    xi_.push_back({0.0, -1.0});
  }
}

double FeInterface::parent_coordinate(int s, double t) const {
  const auto& [xi_a, xi_b] = xi_[static_cast<std::size_t>(s - first_segment_)];
  return xi_a + t * (xi_b - xi_a);
}

void FeInterface::update_nodes(WallSet& walls, std::span<const Vec2> X0, std::span<const double> u,
                               std::span<const double> v, std::span<const double> a) const {
  assert(u.size() == 2 * X0.size() && v.size() == u.size() && a.size() == u.size());
  WallNodes& nodes = walls.nodes();
  for (std::size_t l = 0; l < ncr_.size(); ++l) {
    const auto K = static_cast<std::size_t>(ncr_[l]);
    const auto L = static_cast<std::size_t>(first_node_) + l;
    nodes.x[L] = X0[K] + Vec2(u[2 * K], u[2 * K + 1]); // eq. 60
    nodes.v[L] = Vec2(v[2 * K], v[2 * K + 1]);         // eq. 61
    nodes.a[L] = Vec2(a[2 * K], a[2 * K + 1]);         // eq. 62
  }
}

} // namespace fsi::erp
