#pragma once
// Prescribed rigid motion of a 3-D wall (triangles), the 3-D form of motion.hpp's one-dof
// motions: a scalar profile s(t) (a Motion: its d.x() for a translation, its theta for a
// rotation) drives either
//   a translation  x(t) = X + s(t) e              (e: the direction, its length scales s), or
//   a rotation     x(t) = c + R(k, s(t)) (X - c)  (about the unit axis k through the pivot c,
//                                                  right-handed: counter-clockwise seen from +k).
#include "geometry_erp/motion.hpp"
#include "geometry_erp/triangle_wall_set.hpp"

#include <memory>
#include <span>
#include <vector>

namespace fsi::erp {

/// Position, velocity and acceleration of one node (exact derivatives of the rigid transform).
struct NodeState3 {
  Vec3 x, v, a;
};

class RigidMotion3 {
public:
  /// x = X + s(t) e, s = profile's d.x().
  static RigidMotion3 translation(std::shared_ptr<const Motion> profile, const Vec3& direction);
  /// x = c + R(k, s(t)) (X - c), s = profile's theta; `axis` is normalised (non-zero).
  static RigidMotion3 rotation(std::shared_ptr<const Motion> profile, const Vec3& axis,
                               const Vec3& pivot);

  /// The node with reference position X at time t: for a rotation (Rodrigues) r = R(k, s)(X - c),
  /// v = w x r, a = alpha x r + w x (w x r) with w = s' k, alpha = s'' k.
  NodeState3 at(double t, const Vec3& X) const;

private:
  std::shared_ptr<const Motion> profile_;
  bool rotation_ = false;
  Vec3 direction_ = Vec3::Zero(); ///< e (translation) or the unit axis k (rotation)
  Vec3 pivot_ = Vec3::Zero();
};

/// Nodes of a TriangleWallSet moved rigidly from their reference positions.
struct RigidTriangles3 {
  RigidMotion3 motion;
  int first_node = 0;          ///< the first node of walls.nodes() it moves
  std::vector<Vec3> reference; ///< their positions at rest (X)

  /// Sets x, v, a of nodes first_node .. first_node + reference.size() to time t, then
  /// walls.update() (normals); the fluid refits its triangle index at its next step.
  void move(TriangleWallSet& walls, double t) const;
};

} // namespace fsi::erp
