#pragma once
// The SPH fluid's moving boundary on a 3-D structure's interface mesh: the 2-D design
// (interface_boundary.hpp; RKGC paper, sec. 2.3) on triangular faces. Boundary points on a cubic
// lattice of spacing s <= dp, volume s^3, inside the solid (behind the faces: their corners run
// counter-clockwise seen from the fluid) within `layers` dp of the interface, each anchored at the
// nearest point x(xi, eta) of its nearest face with its offset in that face's corner-triangle frame
// (t1 along corner 0 -> 1, n out of the solid, t2 = n x t1), so that it moves with the face's shape
// functions (face_point) and turns with the triangle. The fluid treats them as moving wall
// particles (the one-sided Riemann wall, eqs. 15-17); their forces go back to the face's nodes with
// the same shape functions N(xi, eta), so the nodal loads sum exactly to the points' forces. When
// the mesh carries the solid's particles (InterfaceMesh3::particle_volume) those are the points
// instead, each at its particle's position with its volume, motion and force.
#include "fluid_sph/sph_fluid.hpp"
#include "fsi/core/interface_mesh.hpp"
#include "particles/box_grid.hpp"

#include <array>
#include <span>
#include <vector>

namespace fsi::sph {

class InterfaceBoundary3 {
public:
  /// Lattice points origin + (i + 1/2, j + 1/2, k + 1/2) s from the first face's corner 0 (s =
  /// spacing, 0: dp), kept when behind their nearest face (at an edge or vertex shared by faces:
  /// behind the mean of their normals) and nearer than layers dp to it; none behind an open edge
  /// of the interface (an edge of one face only), as the 2-D open ends. A mesh with particle nodes
  /// gives those instead (the same test, s unused). Throws InputError for an empty mesh,
  /// layers < 1, s outside (0, dp] or no point.
  InterfaceBoundary3(const InterfaceMesh3& mesh, double dp, int layers = 4, double spacing = 0.0);

  std::size_t size() const { return face_.size(); }
  const InterfaceMesh3& mesh() const { return mesh_; }
  /// Point p's face and the parent coordinates of its anchor.
  std::size_t face(std::size_t p) const { return face_[p][0]; }
  ParentPoint<3> parent(std::size_t p) const { return parent_[p]; }
  /// The points at the reference positions X0 as wall particles of `group` with volume s^3 (a
  /// particle node's own): depth along their normal to their face's plane, and on a convex edge's
  /// bisector the sine of half the angle between the two faces' normals.
  std::vector<WallPoint3> wall_points(int group) const;
  /// Positions and unit normals (into the fluid) of the points for node positions x: a particle
  /// node's x, else x(xi, eta) + a1 t1 + a2 t2 - depth n in the face's frame at x; a point as
  /// near to faces of different normals (an edge's or a corner's bisector) takes their mean.
  void place(const std::vector<Vec3>& x, std::vector<Vec3>& position,
             std::vector<Vec3>& normal) const;
  /// The signed distance of q to the interface at node positions x, > 0 on the fluid's side: to
  /// its flat triangles (the corners; order 2: the four sub-triangles through the mid-side
  /// nodes), signed by the nearest one's normal, at a shared edge or vertex by the sum of theirs.
  double signed_distance(const std::vector<Vec3>& x, const Vec3& q) const;
  /// The same at the reference positions X0 through a grid of the faces: equal to the scan over
  /// all faces bit for bit (see Reach in the source), at the cost of the faces near q.
  double signed_distance(const Vec3& q) const;
  /// Per point: sum_k N_k(xi, eta) value_k over its face's nodes; a particle node's own value.
  void interpolate(const std::vector<Vec3>& nodal, std::vector<Vec3>& at_points) const;
  /// Nodal forces f_k += sum_p N_k(xi_p, eta_p) F_p (f sized to the node count, zeroed first); a
  /// particle node's force to itself.
  void distribute(const std::vector<Vec3>& point_force, std::vector<Vec3>& nodal) const;

private:
  static constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  /// Calls scan(faces, reach) with the faces near q (ascending, a superset of those within r) for
  /// r = about reach_, then 2 r, 4 r, ... until `reach` shows the scan ended as one over all
  /// faces would (or none is within r and floor).
  template <class Scan> void scan_near(const Vec3& q, double floor, Scan&& scan) const;
  InterfaceMesh3 mesh_;
  particles::BoxGrid grid_; ///< the faces' boxes at X0, cells of side reach_
  double reach_ = 0.0;      ///< layers dp
  double size_ = 0.0;       ///< the largest face box's diagonal
  /// Per point: its face, then up to two as near with other normals (kNone: none).
  std::vector<std::array<std::size_t, 3>> face_;
  std::vector<std::size_t> node_; ///< the particle node a point is (or kNone)
  std::vector<ParentPoint<3>> parent_;
  std::vector<Vec3> offset_; ///< (a1, a2, depth) in the face's frame
  std::vector<double> volume_;
};

} // namespace fsi::sph
