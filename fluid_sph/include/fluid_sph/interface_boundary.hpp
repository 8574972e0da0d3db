#pragma once
// The SPH fluid's moving boundary on a structure's interface mesh (RKGC paper, sec. 2.3; issue
// 18): boundary points at a spacing s <= dp, volume s^2, inside the solid (on the LEFT of
// a -> b) within `layers` dp of the interface (s = dp_S: a TL-SPH solid's own lattice, the
// particles the reference code's fluid sees), each anchored at the nearest point x(xi) of its
// nearest edge with its offset in that edge chord's frame, so that it moves with the edge's shape
// functions (edge_point) and turns with the chord. The fluid treats them as moving wall particles
// (the one-sided Riemann wall, eqs. 15-17); their forces go back to the edge nodes with the same
// shape functions N(xi), so the nodal loads sum exactly to the points' forces and their moment
// equals that of the forces placed at the anchors x(xi). When the mesh carries the solid's
// particles (InterfaceMesh::particle_volume: a TL-SPH solid with interface_particles) those are
// the points instead, each at its particle's position and with its volume, motion and force
// (the reference code's fluid sees the solid's particles); the chord frame of the nearest edge
// still gives its normal and depth.
#include "fluid_sph/sph_fluid.hpp"
#include "fsi/core/interface_mesh.hpp"

#include <vector>

namespace fsi::sph {

class InterfaceBoundary {
public:
  /// Lattice points origin + ((i + 1/2) s, (j + 1/2) s) from the first edge's node a (s =
  /// spacing, 0: dp), kept when on the solid side of their nearest edge (at a vertex shared by
  /// two edges: of the mean of their normals) and nearer than layers dp to it; none behind an
  /// open end of the interface (4 layers at s = dp along a straight edge, as the dummies of a
  /// wall). A mesh with particle nodes gives those instead (the same test, s unused). Throws
  /// InputError for an empty mesh, layers < 1, s outside (0, dp] or no point.
  InterfaceBoundary(const InterfaceMesh& mesh, double dp, int layers = 4, double spacing = 0.0);

  std::size_t size() const { return xi_.size(); }
  const InterfaceMesh& mesh() const { return mesh_; }
  /// Point p's edge, parent coordinate of its anchor, offset along the chord and depth behind it.
  std::size_t edge(std::size_t p) const { return edge_[p]; }
  double xi(std::size_t p) const { return xi_[p]; }
  double along(std::size_t p) const { return along_[p]; }
  double depth(std::size_t p) const { return depth_[p]; }
  /// The points at the reference positions X0, as wall particles of `group` of volume s^2 (a
  /// particle's own volume); their
  /// depth is along their normal to their edge's chord line (on a corner's bisector: to the
  /// corner), and a point on a convex corner's bisector gets the sine of half the angle between
  /// the two normals.
  std::vector<WallPoint> wall_points(int group) const;
  /// Positions and unit normals (into the fluid) of the points for node positions `x`: a
  /// particle node's x, else x(xi) + along t - depth n with (t, n) the chord's tangent and
  /// fluid-side normal; the normal of a point as near to two edges (a corner's bisector) is the
  /// mean of theirs.
  void place(const std::vector<Vec2>& x, std::vector<Vec2>& position,
             std::vector<Vec2>& normal) const;
  /// The signed distance of q to the interface at node positions x, > 0 on the fluid's side: to
  /// its chords (a -> m -> b; a -> b for order 1), signed by the nearest chord's normal, at a
  /// vertex by the sum of the normals of the chords that meet there (the through-a-wall guard's
  /// exact surface, SphFluid's distances).
  double signed_distance(const std::vector<Vec2>& x, const Vec2& q) const;
  /// Per point: sum_k N_k(xi) value_k over its edge's nodes (e.g. nodal accelerations); a
  /// particle node's own value.
  void interpolate(const std::vector<Vec2>& nodal, std::vector<Vec2>& at_points) const;
  /// Nodal forces f_k += sum_p N_k(xi_p) F_p (f sized to the node count first, zeroed); a
  /// particle node's force to itself.
  void distribute(const std::vector<Vec2>& point_force, std::vector<Vec2>& nodal) const;

private:
  InterfaceMesh mesh_;
  std::vector<std::size_t> edge_, tie_; ///< nearest edge; an edge as near (or none)
  std::vector<std::size_t> node_;       ///< the particle node a point is (or none)
  std::vector<double> xi_, along_, depth_, volume_;
  double spacing_ = 0.0;
};

} // namespace fsi::sph
