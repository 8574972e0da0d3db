#pragma once
// Polygon walls from the fluid-structure interface of a quadratic (T6) FE mesh (eqs. 47-51,
// 60-62), given as plain arrays so this library does not depend on the FE code.
//
// Edge convention: an interface edge is the triple (K0, Km, K1) of FE node indices, corner,
// mid-side, corner, ordered so that the SOLID is on the LEFT of K0 -> K1 (counter-clockwise
// around the solid, the order of a T6 element's own edges). Its parent coordinate is
// xi = -1 at K0, 0 at Km, +1 at K1. Each edge becomes two flat segments through its mid node,
// directed K1 -> Km and Km -> K0 so that the fluid is on their left (wall_set.hpp).
//
// The polygon nodes are exactly the FE nodes on the interface: NCR maps polygon node L to FE
// node K (eq. 50) and is a bijection between interface nodes (eq. 51).
#include "fsi/core/types.hpp"
#include "geometry_erp/wall_set.hpp"

#include <array>
#include <span>
#include <vector>

namespace fsi::erp {

/// Quadratic edge shape functions at parent coordinate xi in [-1, 1]:
/// N0 = xi (xi - 1) / 2 (node K0), Nm = 1 - xi^2 (node Km), N1 = xi (xi + 1) / 2 (node K1).
inline std::array<double, 3> edge_shape_functions(double xi) {
  return {0.5 * xi * (xi - 1.0), 1.0 - xi * xi, 0.5 * xi * (xi + 1.0)};
}

class FeInterface {
public:
  /// Adds the interface edges to `walls` with group id `group`. X0 holds the reference positions
  /// of all FE nodes. Throws fsi::InputError on a node index outside X0 or a zero-length segment.
  FeInterface(WallSet& walls, std::span<const Vec2> X0, std::span<const std::array<int, 3>> edges,
              int group);

  /// K = NCR(L) for a polygon node L of this interface.
  int fe_node(int L) const { return ncr_[static_cast<std::size_t>(L - first_node_)]; }
  /// L = NCR^-1(K), or -1 if FE node K is not on this interface.
  int polygon_node(int K) const { return ncr_inverse_[static_cast<std::size_t>(K)]; }
  /// Interface nodes of the polygon: L in [first_node, first_node + node_count).
  int first_node() const { return first_node_; }
  int node_count() const { return static_cast<int>(ncr_.size()); }
  int first_segment() const { return first_segment_; }
  int segment_count() const { return static_cast<int>(edge_of_segment_.size()); }

  /// FE edge (index into the constructor's `edges`) that wall segment s belongs to.
  int edge(int s) const { return edge_of_segment_[static_cast<std::size_t>(s - first_segment_)]; }
  /// Parent coordinate on that edge of the point at local coordinate t on segment s (t = 0 at
  /// the segment's node a): xi = xi_a + t (xi_b - xi_a); the mid node is xi = 0.
  double parent_coordinate(int s, double t) const;
  /// Which half of its FE edge segment s is: 0 for Km -> K0 (xi in [-1, 0]), 1 for K1 -> Km.
  int half(int s) const { return (s - first_segment_) % 2 == 0 ? 1 : 0; }
  /// The FE edge's nodes (K0, Km, K1).
  const std::array<int, 3>& edge_nodes(int e) const { return edges_[static_cast<std::size_t>(e)]; }

  /// FE nodes and shape-function weights that share a point load at local coordinate t on
  /// segment s (eq. 58): node K[k] receives N[k] times the load; the weights sum to 1.
  struct LoadWeights {
    std::array<int, 3> K;
    std::array<double, 3> N;
  };
  LoadWeights load_weights(int s, double t) const {
    return {edge_nodes(edge(s)), edge_shape_functions(parent_coordinate(s, t))};
  }

  /// Eqs. 60-62: x_L = X0_K + u_K, v_L = v_K, a_L = a_K for every interface node, with u, v, a
  /// the FE arrays interleaved by degree of freedom (component c of node K at 2K + c).
  void update_nodes(WallSet& walls, std::span<const Vec2> X0, std::span<const double> u,
                    std::span<const double> v, std::span<const double> a) const;

private:
  int first_node_ = 0, first_segment_ = 0;
  std::vector<int> ncr_;                  // L - first_node -> K
  std::vector<int> ncr_inverse_;          // K -> L, -1 off the interface
  std::vector<std::array<int, 3>> edges_; // (K0, Km, K1)
  std::vector<int> edge_of_segment_;      // s - first_segment -> edge
  std::vector<std::array<double, 2>> xi_; // s - first_segment -> (xi at a, xi at b)
};

} // namespace fsi::erp
