#pragma once
// The 3-D ERP wall: a soup of flat triangles over shared nodes (eqs. 18-19 with polygons of three
// nodes), the 3-D counterpart of WallSet.
//
// Fluid side convention: triangle {a, b, c} has the fluid on the side of its normal
// n = (b - a) x (c - a) / |(b - a) x (c - a)|, i.e. a, b, c run counter-clockwise seen from the
// fluid. A closed surface whose normals point into the volume it encloses holds fluid inside (a
// tank); one whose normals point out keeps fluid outside (an obstacle).
//
// Nodes are struct-of-arrays x, v, a (NodeMotion3), writable every step; call update() after
// moving them so the normals follow. Every triangle carries a group id chosen by the caller.
#include "fsi/core/closest_on_triangle.hpp"
#include "fsi/core/node_motion.hpp"
#include "fsi/core/types.hpp"

#include <Eigen/Geometry> // cross products

#include <array>
#include <span>
#include <vector>

namespace fsi::erp {

/// Triangle nodes, struct-of-arrays.
using TriangleWallNodes = NodeMotion3;

/// Triangles t, struct-of-arrays: node[t] = {a, b, c}, fluid on the side of (b - a) x (c - a).
struct WallTriangles {
  std::vector<std::array<int, 3>> node;
  std::vector<int> group;
  std::size_t size() const { return node.size(); }
};

/// The feature of a triangle a nearest point lies on (fsi/core/closest_on_triangle.hpp).
using TriangleFeature = fsi::TriangleFeature;

/// Indices of what one add_triangles call created.
struct TriangleRange {
  int first_node = 0, node_count = 0, first_triangle = 0, triangle_count = 0;
};

class TriangleWallSet {
public:
  /// Appends the nodes `points` and the triangles over them (indices into `points`), then
  /// update(). Throws fsi::InputError, adding nothing, on an index outside `points`, a repeated
  /// index or a degenerate triangle (|(b - a) x (c - a)| <= 1e-12 of its longest edge squared).
  TriangleRange add_triangles(std::span<const Vec3> points,
                              std::span<const std::array<int, 3>> triangles, int group);

  /// Recomputes the face normals and the pseudo-normals at the current node positions.
  void update();

  TriangleWallNodes& nodes() { return nodes_; }
  const TriangleWallNodes& nodes() const { return nodes_; }
  const WallTriangles& triangles() const { return triangles_; }

  /// Unit fluid normal of triangle t (as of the last update()).
  const Vec3& face_normal(int t) const { return face_normal_[static_cast<std::size_t>(t)]; }
  /// Angle-weighted pseudo-normal (Baerentzen & Aanaes 2005) of a feature of triangle t: the face
  /// normal; for an edge the normalised sum of its triangles' normals (each spans an angle pi
  /// about the edge); for a vertex the sum of its triangles' normals weighted by their angles
  /// there, normalised. Falls back to t's face normal where the sum vanishes (folded surfaces).
  Vec3 pseudo_normal(int t, TriangleFeature feature) const;
  /// True for an edge with one triangle, or a vertex on such an edge: the border of an open
  /// surface, beyond which there is no solid.
  bool open(int t, TriangleFeature feature) const;

private:
  void build_edges();

  TriangleWallNodes nodes_;
  WallTriangles triangles_;
  std::vector<int> edge_of_;                                  // edge id of (t, k), 3 per triangle
  std::vector<int> edge_count_;                               // triangles on each edge
  std::vector<unsigned char> open_node_;                      // node on an open edge
  std::vector<Vec3> face_normal_, edge_normal_, node_normal_; // node/edge: zero if undefined
};

} // namespace fsi::erp
