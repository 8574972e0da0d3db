#include "fluid_sph/interface_boundary.hpp"

#include "fsi/core/error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fsi::sph {

namespace {
constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();

// Unit tangent a -> b of edge e's chord and its normal into the fluid (the right: the solid is
// on the left).
std::pair<Vec2, Vec2> chord_frame(const InterfaceMesh& mesh, const std::vector<Vec2>& x,
                                  std::size_t e) {
  const Vec2 t = (x[mesh.edges[e][2]] - x[mesh.edges[e][0]]).normalized();
  return {t, Vec2(t.y(), -t.x())};
}
} // namespace

InterfaceBoundary::InterfaceBoundary(const InterfaceMesh& mesh, double dp, int layers,
                                     double spacing)
    : mesh_(mesh), spacing_(spacing > 0.0 ? spacing : dp) {
  if (mesh.edges.empty()) throw InputError("fluid_sph: the interface mesh has no edge");
  if (layers < 1) throw InputError("fluid_sph: interface layers " + std::to_string(layers));
  if (!(spacing >= 0.0 && spacing <= dp))
    throw InputError("fluid_sph: interface spacing " + std::to_string(spacing) +
                     " outside (0, dp]");
  const std::size_t none = kNone, m = mesh.edges.size();
  // Neighbour edges through the end nodes (b of one edge = a of the next).
  std::vector<std::size_t> starting(mesh.node_count(), none), ending(mesh.node_count(), none);
  for (std::size_t e = 0; e < m; ++e) starting[mesh.edges[e][0]] = e, ending[mesh.edges[e][2]] = e;
  Vec2 lo = mesh.X0[mesh.edges[0][0]], hi = lo;
  for (const auto& k : mesh.edges)
    for (std::size_t j : {k[0], k[2]}) lo = lo.cwiseMin(mesh.X0[j]), hi = hi.cwiseMax(mesh.X0[j]);
  // A candidate point is kept on the solid side of its nearest edge (at a shared vertex: of the
  // two edges' mean normal) within `layers` dp of the interface, as the dummies of a wall
  // polyline; open ends of the interface get none.
  const double depth = layers * dp;
  auto keep = [&](const Vec2& q, std::size_t node, double volume) {
    double best = std::numeric_limits<double>::max(), xi_best = 0.0, side = 0.0;
    std::size_t e_best = none, e_tie = none;
    bool open_end = false;
    for (std::size_t e = 0; e < m; ++e) {
      const Vec2 a = mesh.X0[mesh.edges[e][0]], ab = mesh.X0[mesh.edges[e][2]] - a;
      const double t = std::clamp((q - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
      const double dist = (q - a - t * ab).norm();
      // As near as the best so far, at a corner (not the opposite face of a thin part).
      const bool corner = e_best != none && (chord_frame(mesh, mesh.X0, e).second +
                                             chord_frame(mesh, mesh.X0, e_best).second)
                                                    .norm() > 0.5;
      if (dist < best + 1e-9 * dp && dist > best - 1e-9 * dp && corner) e_tie = e;
      if (dist >= best - 1e-9 * dp) continue;
      best = dist, e_best = e, xi_best = 2.0 * t - 1.0, e_tie = none;
      Vec2 n = chord_frame(mesh, mesh.X0, e).second;
      open_end = false;
      if (t <= 0.0 || t >= 1.0) { // nearest feature: a vertex
        const std::size_t v = mesh.edges[e][t <= 0.0 ? 0 : 2];
        const std::size_t other = t <= 0.0 ? ending[v] : starting[v];
        if (other == none)
          open_end = true;
        else
          n = (n + chord_frame(mesh, mesh.X0, other).second).normalized();
        side = (q - mesh.X0[v]).dot(n);
      } else {
        side = (q - a).dot(n);
      }
    }
    if (open_end || best >= depth || side >= 0.0) return;
    // Anchored at the nearest point of the edge, offset in the chord's frame.
    const auto [t0, n0] = chord_frame(mesh, mesh.X0, e_best);
    const Vec2 r = q - edge_point(mesh, mesh.X0, e_best, xi_best);
    edge_.push_back(e_best);
    tie_.push_back(e_tie);
    node_.push_back(node);
    xi_.push_back(xi_best);
    along_.push_back(r.dot(t0));
    depth_.push_back(-r.dot(n0));
    volume_.push_back(volume);
  };
  if (!mesh.particle_volume.empty()) { // the solid's own particles
    for (std::size_t k = mesh.first_particle(); k < mesh.node_count(); ++k)
      keep(mesh.X0[k], k, mesh.particle_volume[k - mesh.first_particle()]);
  } else { // lattice points at (i + 1/2) s from the first node
    const double s = spacing_;
    const Vec2 origin = mesh.X0[mesh.edges[0][0]];
    const int i0 = static_cast<int>(std::floor((lo.x() - depth - origin.x()) / s)) - 1;
    const int i1 = static_cast<int>(std::ceil((hi.x() + depth - origin.x()) / s)) + 1;
    const int j0 = static_cast<int>(std::floor((lo.y() - depth - origin.y()) / s)) - 1;
    const int j1 = static_cast<int>(std::ceil((hi.y() + depth - origin.y()) / s)) + 1;
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) keep(origin + Vec2((i + 0.5) * s, (j + 0.5) * s), none, s * s);
  }
  if (edge_.empty()) throw InputError("fluid_sph: no boundary point fits behind the interface");
}

std::vector<WallPoint> InterfaceBoundary::wall_points(int group) const {
  std::vector<Vec2> x, n;
  place(mesh_.X0, x, n);
  std::vector<WallPoint> out(size());
  for (std::size_t p = 0; p < size(); ++p) {
    // Depth along the point's normal to its edge's chord line: depth_ on a face; on a corner's
    // bisector depth_ / cos(half the angle), the distance to the corner.
    const Vec2 n0 = chord_frame(mesh_, mesh_.X0, edge_[p]).second;
    const double d = depth_[p] / n[p].dot(n0);
    // A convex corner: the anchor on the edge is behind the other edge's line (at a concave one
    // both are the corner).
    double corner = 0.0;
    if (tie_[p] != kNone) {
      const Vec2 n1 = chord_frame(mesh_, mesh_.X0, tie_[p]).second;
      const Vec2 anchor = edge_point(mesh_, mesh_.X0, edge_[p], xi_[p]);
      if ((anchor - mesh_.X0[mesh_.edges[tie_[p]][0]]).dot(n1) < -1e-9 * depth_[p])
        corner = 0.5 * (n0 - n1).norm();
    }
    out[p] = {x[p], n[p], group, d, corner, volume_[p]};
  }
  return out;
}

void InterfaceBoundary::place(const std::vector<Vec2>& x, std::vector<Vec2>& position,
                              std::vector<Vec2>& normal) const {
  position.resize(size());
  normal.resize(size());
  for (std::size_t p = 0; p < size(); ++p) {
    const auto [t, n] = chord_frame(mesh_, x, edge_[p]);
    // On the bisector of a corner (as near to two edges): the mean of their normals.
    normal[p] = tie_[p] == kNone ? n : (n + chord_frame(mesh_, x, tie_[p]).second).normalized();
    position[p] =
        node_[p] != kNone
            ? x[node_[p]]
            : Vec2(edge_point(mesh_, x, edge_[p], xi_[p]) + along_[p] * t - depth_[p] * n);
  }
}

double InterfaceBoundary::signed_distance(const std::vector<Vec2>& x, const Vec2& q) const {
  double best = std::numeric_limits<double>::max();
  Vec2 foot = Vec2::Zero(), normal = Vec2::Zero();
  auto chord = [&](const Vec2& a, const Vec2& b) {
    const Vec2 ab = b - a;
    const double t = std::clamp((q - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    const Vec2 f = a + t * ab, n = Vec2(ab.y(), -ab.x()).normalized();
    const double d = (q - f).norm(), tie = 1e-12 * (d + ab.norm());
    if (d < best - tie)
      best = d, foot = f, normal = n;
    else if (d <= best + tie && (f - foot).norm() <= tie) // the same vertex, from the next chord
      normal += n;
  };
  for (const auto& k : mesh_.edges) {
    if (mesh_.order == 1) {
      chord(x[k[0]], x[k[2]]);
    } else {
      chord(x[k[0]], x[k[1]]);
      chord(x[k[1]], x[k[2]]);
    }
  }
  return (q - foot).dot(normal) >= 0.0 ? best : -best;
}

void InterfaceBoundary::interpolate(const std::vector<Vec2>& nodal,
                                    std::vector<Vec2>& at_points) const {
  at_points.resize(size());
  for (std::size_t p = 0; p < size(); ++p)
    at_points[p] = node_[p] != kNone ? nodal[node_[p]] : edge_point(mesh_, nodal, edge_[p], xi_[p]);
}

void InterfaceBoundary::distribute(const std::vector<Vec2>& point_force,
                                   std::vector<Vec2>& nodal) const {
  nodal.assign(mesh_.node_count(), Vec2::Zero());
  for (std::size_t p = 0; p < size(); ++p) {
    if (node_[p] != kNone) {
      nodal[node_[p]] += point_force[p];
      continue;
    }
    const auto N = edge_shape_functions(mesh_.order, xi_[p]);
    const auto& k = mesh_.edges[edge_[p]];
    for (int j = 0; j < 3; ++j) nodal[k[j]] += N[j] * point_force[p];
  }
}

} // namespace fsi::sph
