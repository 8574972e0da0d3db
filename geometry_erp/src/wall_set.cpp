#include "geometry_erp/wall_set.hpp"

#include "fsi/core/error.hpp"
#include "fsi/core/state_archive.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <string>

namespace fsi::erp {

int WallSet::add_node(const Vec2& x) {
  nodes_.x.push_back(x);
  nodes_.v.push_back(Vec2::Zero());
  nodes_.a.push_back(Vec2::Zero());
  incident_.emplace_back();
  return static_cast<int>(nodes_.size()) - 1;
}

int WallSet::add_segment(int a, int b, int group) {
  assert(a >= 0 && b >= 0 && a < static_cast<int>(nodes_.size()) &&
         b < static_cast<int>(nodes_.size()));
  const auto ua = static_cast<std::size_t>(a), ub = static_cast<std::size_t>(b);
  if (!((nodes_.x[ub] - nodes_.x[ua]).squaredNorm() > 0.0))
    throw InputError("wall group " + std::to_string(group) + ": zero-length segment at (" +
                     std::to_string(nodes_.x[ua].x()) + ", " + std::to_string(nodes_.x[ua].y()) +
                     ")");
  segments_.node.push_back({a, b});
  segments_.group.push_back(group);
  const int s = static_cast<int>(segments_.size()) - 1;
  incident_[ua].push_back(s);
  incident_[ub].push_back(s);
  return s;
}

WallRange WallSet::add_polyline(std::span<const Vec2> points, bool closed, int group) {
  if (points.size() < 2)
    throw InputError("wall group " + std::to_string(group) + ": a polyline needs two points");
  WallRange range;
  range.first_node = static_cast<int>(nodes_.size());
  range.first_segment = static_cast<int>(segments_.size());
  for (const Vec2& p : points) add_node(p);
  const int n = static_cast<int>(points.size());
  for (int k = 0; k + 1 < n; ++k)
    add_segment(range.first_node + k, range.first_node + k + 1, group);
  if (closed) add_segment(range.first_node + n - 1, range.first_node, group);
  range.node_count = n;
  range.segment_count = static_cast<int>(segments_.size()) - range.first_segment;
  return range;
}

WallRange WallSet::add_rigid_polyline(std::span<const Vec2> points, bool closed, int group,
                                      Vec2 pivot, std::shared_ptr<const Motion> motion) {
  const WallRange range = add_polyline(points, closed, group);
  rigid_.push_back({range.first_node, range.node_count,
                    std::vector<Vec2>(points.begin(), points.end()), pivot, std::move(motion)});
  move_rigid(0.0);
  return range;
}

void WallSet::move_rigid(double t) {
  for (const RigidPolyline& wall : rigid_) {
    const RigidKinematics k = wall.motion->at(t);
    for (int i = 0; i < wall.node_count; ++i) {
      const auto L = static_cast<std::size_t>(wall.first_node + i);
      const NodeState state = rigid_node_state(k, wall.pivot, wall.X[static_cast<std::size_t>(i)]);
      nodes_.x[L] = state.x;
      nodes_.v[L] = state.v;
      nodes_.a[L] = state.a;
    }
  }
}

Vec2 WallSet::segment_normal(int s) const {
  const auto& [a, b] = segments_.node[static_cast<std::size_t>(s)];
  const Vec2 ab = nodes_.x[static_cast<std::size_t>(b)] - nodes_.x[static_cast<std::size_t>(a)];
  return Vec2(-ab.y(), ab.x()).normalized();
}

Vec2 WallSet::node_normal(int L, int fallback_segment) const {
  Vec2 sum = Vec2::Zero();
  for (const int s : incident_[static_cast<std::size_t>(L)]) sum += segment_normal(s);
  const double norm = sum.norm();
  // A vanishing sum means two incident normals cancel: no side is defined by the node.
  if (norm < 1e-12) return segment_normal(fallback_segment);
  return sum / norm;
}

std::optional<ConvexJoint> WallSet::convex_joint(int L) const {
  const auto& incident = incident_[static_cast<std::size_t>(L)];
  if (incident.size() != 2) return std::nullopt;
  int in = incident[0], out = incident[1];
  if (segments_.node[static_cast<std::size_t>(in)][1] != L) std::swap(in, out);
  const auto& [a, l_in] = segments_.node[static_cast<std::size_t>(in)];
  const auto& [l_out, b] = segments_.node[static_cast<std::size_t>(out)];
  if (l_in != L || l_out != L) return std::nullopt; // two segments meeting head to head
  const Vec2& x = nodes_.x[static_cast<std::size_t>(L)];
  const Vec2 u_in = (x - nodes_.x[static_cast<std::size_t>(a)]).normalized();
  const Vec2 u_out = (nodes_.x[static_cast<std::size_t>(b)] - x).normalized();
  // Fluid on the left: a right turn (u_in x u_out < 0) puts the solid inside the angle.
  if (u_in.x() * u_out.y() - u_in.y() * u_out.x() >= 0.0) return std::nullopt;
  const double turn = std::acos(std::clamp(u_in.dot(u_out), -1.0, 1.0));
  if (turn <= convex_joint_min_turn) return std::nullopt;
  return ConvexJoint{in, out, Vec2(-u_in.y(), u_in.x()), Vec2(-u_out.y(), u_out.x()), turn};
}

void WallSet::write_state(StateArchive& archive, const std::string& prefix) const {
  archive.put(prefix + "x", flatten(nodes_.x));
  archive.put(prefix + "v", flatten(nodes_.v));
  archive.put(prefix + "a", flatten(nodes_.a));
}

void WallSet::read_state(const StateArchive& archive, const std::string& prefix) {
  const std::size_t n = 2 * nodes_.size();
  nodes_.x = unflatten(archive.reals(prefix + "x", n));
  nodes_.v = unflatten(archive.reals(prefix + "v", n));
  nodes_.a = unflatten(archive.reals(prefix + "a", n));
}

} // namespace fsi::erp
