// Dummy wall particles (method notes' dummy state, eqs. 15-17): the layers behind each wall
// polyline, and their rigid motion over an acoustic step.
#include "fluid_sph/sph_fluid.hpp"

#include "fsi/core/error.hpp"
#include "fsi/core/parallel.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fsi::sph {

template <int D>
void BasicSphFluid<D>::fill_walls(const std::vector<WallPolyline>& walls) requires(D == 2) {
  // Dummy particles: lattice points at (i + 1/2) dp from each polyline's first point that lie on
  // the wall side (right of the nearest segment; at a vertex, of the sum of the two normals) within
  // 4 dp of the polyline. Their normal is that of the nearest feature, into the fluid, and their
  // depth the distance behind that feature's line along it ((k + 1/2) dp for layer k of a wall).
  const double dp = options_.dp, depth = 4.0 * dp;
  std::vector<Vec2> xs, ns;
  std::vector<double> ds;
  std::vector<std::uint32_t> groups;
  for (const WallPolyline& w : walls) {
    const std::size_t m = w.points.size();
    if (m < 2) throw InputError("fluid_sph: a wall polyline needs >= 2 points");
    if (w.group < 0) throw InputError("fluid_sph: wall group " + std::to_string(w.group) + " < 0");
    const std::size_t segs = w.closed ? m : m - 1;
    Vec2 bmin = w.points[0], bmax = w.points[0];
    for (const Vec2& q : w.points) bmin = bmin.cwiseMin(q), bmax = bmax.cwiseMax(q);
    const Vec2 origin = w.points[0];
    const int i0 = static_cast<int>(std::floor((bmin.x() - depth - origin.x()) / dp)) - 1;
    const int i1 = static_cast<int>(std::ceil((bmax.x() + depth - origin.x()) / dp)) + 1;
    const int j0 = static_cast<int>(std::floor((bmin.y() - depth - origin.y()) / dp)) - 1;
    const int j1 = static_cast<int>(std::ceil((bmax.y() + depth - origin.y()) / dp)) + 1;
    const auto normal = [&](std::size_t s) { // left normal of segment s
      const Vec2 d = (w.points[(s + 1) % m] - w.points[s]).normalized();
      return Vec2(-d.y(), d.x());
    };
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) {
        const Vec2 q = origin + Vec2((i + 0.5) * dp, (j + 0.5) * dp);
        double best = std::numeric_limits<double>::max();
        Vec2 n_best = Vec2::Zero();
        bool open_end = false;
        double side = 0.0;
        for (std::size_t s = 0; s < segs; ++s) {
          const Vec2 a = w.points[s], b = w.points[(s + 1) % m];
          const Vec2 ab = b - a;
          const double t = std::clamp((q - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
          const double dist = (q - (a + t * ab)).norm();
          if (dist >= best - 1e-12 * dp) continue;
          best = dist;
          Vec2 n = normal(s);
          open_end = false;
          if (t <= 0.0 || t >= 1.0) { // nearest feature is a vertex
            const bool at_a = t <= 0.0;
            const std::size_t v = at_a ? s : (s + 1) % m;
            const bool has_other = w.closed || (at_a ? s > 0 : s + 1 < segs);
            if (has_other) {
              const std::size_t other = at_a ? (s + segs - 1) % segs : (s + 1) % segs;
              n = (n + normal(other)).normalized();
            } else {
              open_end = true;
            }
            side = (q - w.points[v]).dot(n);
          } else {
            side = (q - a).dot(n);
          }
          n_best = n;
        }
        if (open_end || best >= depth || side >= 0.0) continue;
        xs.push_back(q);
        ns.push_back(n_best);
        ds.push_back(-side);
        groups.push_back(static_cast<std::uint32_t>(w.group));
      }
  }
  const std::size_t nw = xs.size();
  walls_.fields.resize(nw);
  for (std::size_t a = 0; a < nw; ++a) {
    walls_.group[a] = groups[a];
    for (int c = 0; c < D; ++c) {
      walls_.x[c][a] = walls_.x0[c][a] = walls_.xb[c][a] = xs[a][c];
      walls_.n[c][a] = walls_.n0[c][a] = ns[a][c];
    }
    walls_.depth[a] = ds[a];
    walls_.vol[a] = dp * dp;
  }
}

template <int D> void BasicSphFluid<D>::move_walls(double dt) requires(D == 2) {
  if (motions_.empty()) return;
  for (std::size_t g = 0; g < motions_.size(); ++g) {
    if (!motions_[g]) continue;
    const RigidMotion m0 = motions_[g](t_), m1 = motions_[g](t_ + dt);
    const double c0 = std::cos(m0.theta), s0 = std::sin(m0.theta);
    const double c1 = std::cos(m1.theta), s1 = std::sin(m1.theta);
    const double inv_dt = 1.0 / dt;
    parallel_for(walls_.size(), [&](std::size_t a) {
      if (walls_.group[a] != g) return;
      auto &x = walls_.x, &n = walls_.n, &n0 = walls_.n0, &v = walls_.v, &acc = walls_.a;
      const Vec2 X(walls_.x0[0][a] - m0.centre.x(), walls_.x0[1][a] - m0.centre.y());
      const Vec2 r0(c0 * X.x() - s0 * X.y(), s0 * X.x() + c0 * X.y());
      const Vec2 r1(c1 * X.x() - s1 * X.y(), s1 * X.x() + c1 * X.y());
      const Vec2 x0 = m0.centre + m0.d + r0, x1 = m1.centre + m1.d + r1;
      const Vec2 v0 = m0.v + m0.omega * Vec2(-r0.y(), r0.x());
      const Vec2 v1 = m1.v + m1.omega * Vec2(-r1.y(), r1.x());
      // Velocity and acceleration averaged over the acoustic step (eq. 17, ref. [54]).
      v[0][a] = (x1.x() - x0.x()) * inv_dt;
      v[1][a] = (x1.y() - x0.y()) * inv_dt;
      acc[0][a] = (v1.x() - v0.x()) * inv_dt;
      acc[1][a] = (v1.y() - v0.y()) * inv_dt;
      x[0][a] = x1.x();
      x[1][a] = x1.y();
      n[0][a] = c1 * n0[0][a] - s1 * n0[1][a];
      n[1][a] = s1 * n0[0][a] + c1 * n0[1][a];
    });
  }
}

template void BasicSphFluid<2>::fill_walls(const std::vector<WallPolyline>&);
template void BasicSphFluid<2>::move_walls(double);

} // namespace fsi::sph
