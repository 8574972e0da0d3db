#pragma once
// The pressure a wall itself sees at a point of one of its triangles (issue 43, SPHERIC Test 2's
// sensors): the wall force the fluid's particles put on the triangles of the point's plane
// (emps::TriangleForces, the pressure mirror and contact terms of eq. 52, times V_i: the wall
// receives -f at x_wall), averaged over the plane with a 2-D Wendland C2 weight of radius R about
// the point and divided by the same weight's integral over the plane's triangles within R:
//   p = -sum_i w(|x_wall,i - x0|) (-f_i) . n / int_{plane within R} w dA,
// n the plane's fluid normal. A particle at rest beside the wall carries p l0^2 of it, so p is
// the weighted mean of the wall's pressure (positive: the wall is pushed out of the fluid). Not the
// fluid's mean within r_e of the point (the `pressure` probe), which takes in free-surface zeros.
#include "decomposed_particles.hpp"
#include "fluid_emps/emps_fluid.hpp"
#include "fsi_app/scene.hpp"
#include "geometry_erp/triangle_wall_set.hpp"

#include <vector>

namespace fsi::app::emps_plugin {

class WallPointPressure {
public:
  /// The triangles of `walls` in the plane of the one nearest `point` (normals within 1e-9,
  /// planes within 1e-6 R of each other) and the weight's integral over them within `radius`
  /// (the midpoint rule on square cells of side R/64). Throws fsi::InputError when `point` lies
  /// farther than 1e-6 R from every triangle or radius <= 0. The walls must stay where they are.
  WallPointPressure(const erp::TriangleWallSet& walls, const Vec3& point, double radius);

  /// -sum_i w_i f_i over the faces on the plane's triangles within R: what the wall receives,
  /// weighted, N. Its component along -normal() over area() is pressure().
  Vec3 weighted_force(const emps::WallForces3& forces) const;
  /// p from weighted_force's value (summed over processes when decomposed), Pa.
  double pressure(const Vec3& weighted_force) const {
    return 0.0 - weighted_force.dot(n_) / area_; // 0 - : +0, not -0, without a force
  }
  /// The plane's unit fluid normal.
  const Vec3& normal() const { return n_; }
  /// int w dA over the plane's triangles within R, m^2 (pi R^2 / 7 for a whole disc).
  double area() const { return area_; }

private:
  /// Wendland's C2 weight (1 - q)^4 (1 + 4 q), q = r/R < 1 (its integral over the disc is
  /// pi R^2 / 7).
  double weight(double r) const;

  const erp::TriangleWallSet& walls_;
  Vec3 x0_, n_;
  double R_;
  std::vector<char> in_plane_; // by triangle
  double area_ = 0.0;
};

/// The wall_pressure probes of a scene over its fluid's walls, in the scene's order.
class WallPointProbes {
public:
  /// A WallPointPressure for each (its radius absent: r_e). InputError `FILE:LINE:
  /// output.probes[k].point: what` for a point on no wall, `...quantity` when the walls move.
  WallPointProbes(const Scene& scene, const erp::TriangleWallSet& walls, double r_e,
                  bool walls_move);
  /// Collective when decomposed: each probe's p from every process's forces, kept for value().
  void gather(const emps::WallForces3& forces, const DecomposedParticles<3>& ranks);
  /// The probe's p: from the last gather when decomposed, else from `forces`, Pa.
  double value(const ProbeSpec& probe, const emps::WallForces3& forces, bool decomposed) const;

private:
  std::vector<std::string> keys_; // the probes' keys
  std::vector<WallPointPressure> points_;
  std::vector<double> gathered_;
};

} // namespace fsi::app::emps_plugin
