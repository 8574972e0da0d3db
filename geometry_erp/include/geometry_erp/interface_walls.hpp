#pragma once
// Polygon walls from a structure's coupling interface (EMPS-ERP-FEM paper, eqs. 47-51, 60-62).
// The structure describes its interface (fsi::InterfaceMesh: nodes, order-1 or order-2 edges,
// solid on the left of a -> b); this library needs nothing else of it.
//
// The polygon nodes are exactly the interface nodes: NCR maps interface node k to polygon node
// L = first_node + k (eq. 50), a bijection between interface nodes (eq. 51); the structure keeps
// its own map from interface nodes to its nodes. An order-2 edge (a, m, b) becomes two flat
// segments through its mid node, directed b -> m and m -> a so that the fluid is on their left
// (wall_set.hpp); an order-1 edge one segment b -> a. Parent coordinates: xi = -1 at a, 0 at m,
// +1 at b.
#include "fsi/core/interface_mesh.hpp"
#include "fsi/core/node_motion.hpp"
#include "fsi/core/types.hpp"
#include "geometry_erp/wall_set.hpp"

#include <array>
#include <cassert>
#include <span>
#include <vector>

namespace fsi::erp {

/// Eqs. 60-62: the wall nodes first, first + 1, ... take the interface state x, v, a of the
/// interface nodes 0, 1, ... (NCR, eq. 50), in 2-D and 3-D.
template <int D>
void set_interface_nodes(BasicNodeMotion<D>& nodes, int first, std::span<const VecD<D>> x,
                         std::span<const VecD<D>> v, std::span<const VecD<D>> a) {
  assert(v.size() == x.size() && a.size() == x.size() &&
         static_cast<std::size_t>(first) + x.size() <= nodes.size());
  for (std::size_t k = 0; k < x.size(); ++k) {
    const auto L = static_cast<std::size_t>(first) + k;
    nodes.x[L] = x[k]; // eq. 60
    nodes.v[L] = v[k]; // eq. 61
    nodes.a[L] = a[k]; // eq. 62
  }
}

class InterfaceWalls {
public:
  /// Adds the interface's nodes and edges to `walls` with group id `group`. Throws
  /// fsi::InputError on a node index outside the interface, an order other than 1 or 2, or a
  /// zero-length segment.
  InterfaceWalls(WallSet& walls, const InterfaceMesh& mesh, int group);

  /// Interface nodes of the polygon: L in [first_node, first_node + node_count).
  int first_node() const { return first_node_; }
  int node_count() const { return node_count_; }
  int first_segment() const { return first_segment_; }
  int segment_count() const { return static_cast<int>(edge_of_segment_.size()); }
  const InterfaceMesh& mesh() const { return mesh_; }

  /// Interface edge (index into mesh().edges) that wall segment s belongs to.
  int edge(int s) const { return edge_of_segment_[static_cast<std::size_t>(s - first_segment_)]; }
  /// Parent coordinate on that edge of the point at local coordinate t on segment s (t = 0 at
  /// the segment's node a): xi = xi_a + t (xi_b - xi_a).
  double parent_coordinate(int s, double t) const;

  /// Interface nodes and shape-function weights that share a point load at local coordinate t
  /// on segment s (eq. 58): node k[j] receives N[j] times the load; the weights sum to 1.
  struct LoadWeights {
    std::array<std::size_t, 3> k;
    std::array<double, 3> N;
  };
  LoadWeights load_weights(int s, double t) const {
    return {mesh_.edges[static_cast<std::size_t>(edge(s))],
            edge_shape_functions(mesh_.order, parent_coordinate(s, t))};
  }

  /// Eqs. 60-62: x_L, v_L, a_L of every interface node from the structure's interface state.
  void update_nodes(WallSet& walls, std::span<const Vec2> x, std::span<const Vec2> v,
                    std::span<const Vec2> a) const {
    assert(x.size() == static_cast<std::size_t>(node_count_));
    set_interface_nodes(walls.nodes(), first_node_, x, v, a);
  }

private:
  InterfaceMesh mesh_;
  int first_node_ = 0, first_segment_ = 0, node_count_ = 0;
  std::vector<int> edge_of_segment_;      // s - first_segment -> edge
  std::vector<std::array<double, 2>> xi_; // s - first_segment -> (xi at a, xi at b)
};

} // namespace fsi::erp
