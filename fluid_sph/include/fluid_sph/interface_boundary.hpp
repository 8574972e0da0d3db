#pragma once
// The SPH fluid's moving boundary on a structure's interface mesh (RKGC paper, sec. 2.3; issue
// 18): boundary points on each interface edge at spacing <= dp, moving with the edge's shape
// functions (edge_point), in `layers` rows behind the edge (inside the solid, on the LEFT of
// a -> b) at depths (k + 1/2) dp. The fluid treats them as moving wall particles (the one-sided
// Riemann wall, eqs. 15-17); their forces go back to the edge nodes with the same shape
// functions, so the nodal loads sum exactly to the points' forces and their moment equals that
// of the forces placed at the points' edge positions.
#include "fluid_sph/sph_fluid.hpp"
#include "fsi/core/interface_mesh.hpp"

#include <vector>

namespace fsi::sph {

class InterfaceBoundary {
public:
  /// Points for every edge: n_e = ceil(L_e / dp) along it (L_e the reference chord), at
  /// xi_q = -1 + (2 q + 1) / n_e; a point nearer (in X0) to another edge than to its own is
  /// dropped. Throws InputError for an empty mesh or layers < 1.
  InterfaceBoundary(const InterfaceMesh& mesh, double dp, int layers = 4);

  std::size_t size() const { return xi_.size(); }
  const InterfaceMesh& mesh() const { return mesh_; }
  /// Point p's edge, parent coordinate and depth behind the edge.
  std::size_t edge(std::size_t p) const { return edge_[p]; }
  double xi(std::size_t p) const { return xi_[p]; }
  double depth(std::size_t p) const { return depth_[p]; }
  /// The points at the reference positions X0, as wall particles of `group`.
  std::vector<WallPoint> wall_points(int group) const;
  /// Positions and unit normals (into the fluid) of the points for node positions `x`: the edge
  /// point x(xi) minus depth times the chord's fluid-side normal.
  void place(const std::vector<Vec2>& x, std::vector<Vec2>& position,
             std::vector<Vec2>& normal) const;
  /// Per point: sum_k N_k(xi) value_k over its edge's nodes (e.g. nodal accelerations).
  void interpolate(const std::vector<Vec2>& nodal, std::vector<Vec2>& at_points) const;
  /// Nodal forces f_k += sum_p N_k(xi_p) F_p (f sized to the node count first, zeroed).
  void distribute(const std::vector<Vec2>& point_force, std::vector<Vec2>& nodal) const;

private:
  InterfaceMesh mesh_;
  std::vector<std::size_t> edge_;
  std::vector<double> xi_, depth_;
};

} // namespace fsi::sph
