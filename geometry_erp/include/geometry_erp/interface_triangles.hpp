#pragma once
// Triangle walls from a structure's 3-D coupling interface (EMPS-ERP-FEM paper, eqs. 47-51 and
// 60-62 in 3-D; issue 43): the 3-D counterpart of InterfaceWalls. The structure describes its
// interface (fsi::InterfaceMesh3: nodes, 6-node or 3-node faces, corners counter-clockwise seen
// from the fluid); this library needs nothing else of it.
//
// The wall nodes are exactly the interface nodes: NCR maps interface node k to wall node
// L = first_node + k (eq. 50). An order-2 face (corners 0, 1, 2, mid-sides 3 (0-1), 4 (1-2),
// 5 (2-0)) becomes four flat triangles through its mid-side nodes, {0, 3, 5}, {3, 1, 4},
// {5, 4, 2} and {3, 4, 5}, each with the face's orientation, so the fluid is on the side of
// their normals (TriangleWallSet's convention); an order-1 face one triangle {0, 1, 2}.
// A point of a flat triangle at local coordinates (s, t) (x = x_a + s (x_b - x_a) + t (x_c -
// x_a)) lies at the face's parent point interpolated the same way between its vertices' parent
// points, where the face's shape functions share a load among its six nodes (eq. 58 in 3-D).
#include "fsi/core/interface_mesh.hpp"
#include "fsi/core/types.hpp"
#include "geometry_erp/interface_walls.hpp"
#include "geometry_erp/triangle_wall_set.hpp"

#include <array>
#include <span>
#include <vector>

namespace fsi::erp {

class InterfaceTriangles {
public:
  /// Adds the interface's nodes and faces to `walls` with group id `group`. Throws
  /// fsi::InputError, adding nothing, on a node index outside the interface, an order other than
  /// 1 or 2, or a degenerate triangle.
  InterfaceTriangles(TriangleWallSet& walls, const InterfaceMesh3& mesh, int group);

  int first_node() const { return range_.first_node; }
  int node_count() const { return range_.node_count; }
  int first_triangle() const { return range_.first_triangle; }
  int triangle_count() const { return range_.triangle_count; }
  const InterfaceMesh3& mesh() const { return mesh_; }

  /// Interface face (index into mesh().faces) that wall triangle t belongs to.
  int face(int t) const { return face_of_[local(t)]; }
  /// Parent point (xi, eta) on that face of the point at local coordinates (s, t) of triangle
  /// `triangle`.
  ParentPoint<3> parent_point(int triangle, double s, double t) const;

  /// Interface nodes and shape-function weights that share a point load at local coordinates
  /// (s, t) of triangle `triangle` (eq. 58 in 3-D): node k[j] receives N[j] times the load; the
  /// weights sum to 1.
  struct LoadWeights {
    std::array<std::size_t, 6> k;
    std::array<double, 6> N;
  };
  LoadWeights load_weights(int triangle, double s, double t) const;

  /// Eqs. 60-62: x_L, v_L, a_L of every interface node from the structure's interface state.
  /// Call walls.update() afterwards.
  void update_nodes(TriangleWallSet& walls, std::span<const Vec3> x, std::span<const Vec3> v,
                    std::span<const Vec3> a) const {
    set_interface_nodes(walls.nodes(), first_node(), x, v, a);
  }

private:
  std::size_t local(int t) const { return static_cast<std::size_t>(t - range_.first_triangle); }

  InterfaceMesh3 mesh_;
  TriangleRange range_;
  std::vector<int> face_of_;                   // t - first_triangle -> face
  std::vector<std::array<int, 3>> sub_vertex_; // t - first_triangle -> its vertices' face slots
};

} // namespace fsi::erp
