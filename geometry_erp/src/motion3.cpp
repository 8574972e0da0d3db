#include "geometry_erp/motion3.hpp"

#include <cassert>
#include <cmath>

namespace fsi::erp {

RigidMotion3 RigidMotion3::translation(std::shared_ptr<const Motion> profile,
                                       const Vec3& direction) {
  RigidMotion3 m;
  m.profile_ = std::move(profile);
  m.direction_ = direction;
  return m;
}

RigidMotion3 RigidMotion3::rotation(std::shared_ptr<const Motion> profile, const Vec3& axis,
                                    const Vec3& pivot) {
  assert(axis.norm() > 0.0);
  RigidMotion3 m;
  m.profile_ = std::move(profile);
  m.rotation_ = true;
  m.direction_ = axis.normalized();
  m.pivot_ = pivot;
  return m;
}

NodeState3 RigidMotion3::at(double t, const Vec3& X) const {
  const RigidKinematics k = profile_->at(t);
  if (!rotation_)
    return {X + k.d.x() * direction_, k.d_dot.x() * direction_, k.d_ddot.x() * direction_};
  const Vec3& axis = direction_;
  const Vec3 X_c = X - pivot_;
  const double c = std::cos(k.theta), s = std::sin(k.theta);
  // Rodrigues: R v = v cos + (k x v) sin + k (k . v)(1 - cos).
  const Vec3 r = c * X_c + s * axis.cross(X_c) + (1.0 - c) * axis.dot(X_c) * axis;
  const Vec3 w = k.omega * axis, alpha = k.alpha * axis;
  const Vec3 v = w.cross(r);
  return {pivot_ + r, v, alpha.cross(r) + w.cross(v)};
}

void RigidTriangles3::move(TriangleWallSet& walls, double t) const {
  TriangleWallNodes& n = walls.nodes();
  for (std::size_t k = 0; k < reference.size(); ++k) {
    const auto i = static_cast<std::size_t>(first_node) + k;
    const NodeState3 s = motion.at(t, reference[k]);
    n.x[i] = s.x, n.v[i] = s.v, n.a[i] = s.a;
  }
  walls.update();
}

} // namespace fsi::erp
