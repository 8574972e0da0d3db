#include "emps/wall_point_pressure.hpp"

#include "fsi/core/closest_on_triangle.hpp"
#include "fsi/core/error.hpp"
#include "fsi/core/format.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fsi::app::emps_plugin {

namespace {

constexpr double kOnWall = 1e-6; // a point within this many R of a triangle lies on it
constexpr int kSamples = 64;     // lattice points per R for the weight's integral

/// Distance from p to triangle t of `walls`.
double distance(const erp::TriangleWallSet& walls, int t, const Vec3& p) {
  const auto& node = walls.triangles().node[static_cast<std::size_t>(t)];
  const auto& X = walls.nodes().x;
  const Vec3 &a = X[static_cast<std::size_t>(node[0])], &b = X[static_cast<std::size_t>(node[1])],
             &c = X[static_cast<std::size_t>(node[2])];
  return (triangle_point(closest_on_triangle(p, a, b, c), a, b, c) - p).norm();
}

} // namespace

WallPointPressure::WallPointPressure(const erp::TriangleWallSet& walls, const Vec3& point,
                                     double radius)
    : walls_(walls), x0_(point), R_(radius) {
  if (!(radius > 0.0)) throw InputError("radius must be positive");
  const int count = static_cast<int>(walls.triangles().size());
  int nearest = -1;
  double d_min = std::numeric_limits<double>::infinity();
  for (int t = 0; t < count; ++t)
    if (const double d = distance(walls, t, point); d < d_min) d_min = d, nearest = t;
  if (nearest < 0 || d_min > kOnWall * R_)
    throw InputError("the point lies " + significant(d_min, 3) +
                     " m from the nearest wall triangle (it must lie on one)");
  n_ = walls.face_normal(nearest);
  in_plane_.assign(static_cast<std::size_t>(count), 0);
  for (int t = 0; t < count; ++t) {
    const auto& node = walls.triangles().node[static_cast<std::size_t>(t)];
    const Vec3& a = walls.nodes().x[static_cast<std::size_t>(node[0])];
    in_plane_[static_cast<std::size_t>(t)] =
        walls.face_normal(t).dot(n_) > 1.0 - 1e-9 && std::abs((a - x0_).dot(n_)) <= kOnWall * R_;
  }
  // int w dA over the plane's triangles: the midpoint rule on the cells of side h = R/64 about x0
  const Vec3 e1 = n_.unitOrthogonal(), e2 = n_.cross(e1);
  const double h = R_ / kSamples;
  for (int i = -kSamples; i < kSamples; ++i)
    for (int j = -kSamples; j < kSamples; ++j) {
      const double a = h * (i + 0.5), b = h * (j + 0.5), r = std::hypot(a, b);
      if (r >= R_) continue;
      const Vec3 s = x0_ + a * e1 + b * e2;
      for (int t = 0; t < count; ++t)
        if (in_plane_[static_cast<std::size_t>(t)] && distance(walls, t, s) <= kOnWall * R_) {
          area_ += weight(r) * h * h;
          break;
        }
    }
}

double WallPointPressure::weight(double r) const {
  const double q = r / R_;
  return q < 1.0 ? std::pow(1.0 - q, 4) * (1.0 + 4.0 * q) : 0.0;
}

Vec3 WallPointPressure::weighted_force(const emps::WallForces3& forces) const {
  const auto& X = walls_.nodes().x;
  Vec3 sum = Vec3::Zero();
  for (const emps::TriangleForces& face : forces)
    for (std::size_t i = 0; i < face.triangle.size(); ++i) {
      const int t = face.triangle[i];
      if (t < 0 || !in_plane_[static_cast<std::size_t>(t)]) continue;
      const auto& node = walls_.triangles().node[static_cast<std::size_t>(t)];
      const Vec3 x_wall = face.bary[i][0] * X[static_cast<std::size_t>(node[0])] +
                          face.bary[i][1] * X[static_cast<std::size_t>(node[1])] +
                          face.bary[i][2] * X[static_cast<std::size_t>(node[2])];
      sum -= weight((x_wall - x0_).norm()) * face.f[i]; // the wall receives -f (eq. 52)
    }
  return sum;
}

WallPointProbes::WallPointProbes(const Scene& scene, const erp::TriangleWallSet& walls, double r_e,
                                 bool walls_move) {
  for (const ProbeSpec& p : scene.output.probes) {
    if (p.quantity != "wall_pressure") continue;
    if (walls_move)
      fail_at(scene, p.line, p.key + ".quantity",
              "wall_pressure needs walls at rest (no tank_motion, no structures)");
    try {
      points_.emplace_back(walls, *p.point3, p.radius.value_or(r_e));
    } catch (const InputError& e) {
      fail_at(scene, p.line, p.key + ".point", e.what());
    }
    keys_.push_back(p.key);
  }
}

void WallPointProbes::gather(const emps::WallForces3& forces, const DecomposedParticles<3>& ranks) {
  std::vector<double> f; // this process's particles' weighted forces, then every process's
  for (const WallPointPressure& w : points_) {
    const Vec3 fk = w.weighted_force(forces);
    f.insert(f.end(), {fk.x(), fk.y(), fk.z()});
  }
  ranks.sum(f);
  gathered_.clear();
  for (std::size_t k = 0; k < points_.size(); ++k)
    gathered_.push_back(points_[k].pressure(Vec3(f[3 * k], f[3 * k + 1], f[3 * k + 2])));
}

double WallPointProbes::value(const ProbeSpec& probe, const emps::WallForces3& forces,
                              bool decomposed) const {
  const auto k =
      static_cast<std::size_t>(std::find(keys_.begin(), keys_.end(), probe.key) - keys_.begin());
  return decomposed ? gathered_[k] : points_[k].pressure(points_[k].weighted_force(forces));
}

} // namespace fsi::app::emps_plugin
