#pragma once
// Prescribed rigid motion of a wall: translation d(t) and rotation angle theta(t) (radians,
// counter-clockwise) about a pivot c that moves with the translation:
//   x(t) = c + d(t) + R(theta(t)) (X - c)
// for a node at reference position X. One class per kind of motion; SumMotion combines them
// (translations add, angles add).
#include "fsi/core/types.hpp"
#include "geometry_erp/cubic_spline.hpp"

#include <memory>
#include <string>
#include <vector>

namespace fsi::erp {

/// Translation, rotation angle and their first and second time derivatives at one time.
struct RigidKinematics {
  Vec2 d = Vec2::Zero(), d_dot = Vec2::Zero(), d_ddot = Vec2::Zero();
  double theta = 0.0, omega = 0.0, alpha = 0.0;
};

class Motion {
public:
  virtual ~Motion() = default;
  virtual RigidKinematics at(double t) const = 0;
};

/// d(t) = A sin(2 pi t / T + phase).
class SinusoidTranslation final : public Motion {
public:
  SinusoidTranslation(Vec2 amplitude, double period, double phase);
  RigidKinematics at(double t) const override;

private:
  Vec2 amplitude_;
  double period_, phase_;
};

/// theta(t) = A sin(2 pi t / T + phase), A in radians.
class SinusoidRotation final : public Motion {
public:
  SinusoidRotation(double amplitude, double period, double phase);
  RigidKinematics at(double t) const override;

private:
  double amplitude_, period_, phase_;
};

/// d(t) from a CSV table with columns time, dx, dy (values times `scale`), interpolated by a
/// natural cubic spline. Before the first and after the last time the end value is held.
class TableTranslation final : public Motion {
public:
  explicit TableTranslation(const std::string& csv_path, double scale = 1.0);
  /// Along one direction: columns time, s; d(t) = s(t) `direction` (its length scales s).
  TableTranslation(const std::string& csv_path, const Vec2& direction);
  RigidKinematics at(double t) const override;

private:
  CubicSpline dx_, dy_;
};

/// theta(t) from a CSV table with columns time, angle (times `scale`: pi/180 for degrees),
/// interpolated by a natural cubic spline; end values held outside the table.
class TableRotation final : public Motion {
public:
  explicit TableRotation(const std::string& csv_path, double scale = 1.0);
  RigidKinematics at(double t) const override;

private:
  CubicSpline theta_;
};

/// Sum of motions: d = sum d_k, theta = sum theta_k (and likewise for the derivatives).
class SumMotion final : public Motion {
public:
  explicit SumMotion(std::vector<std::shared_ptr<const Motion>> parts);
  RigidKinematics at(double t) const override;

private:
  std::vector<std::shared_ptr<const Motion>> parts_;
};

/// Position, velocity and acceleration of the node with reference position X under kinematics k
/// about pivot c (exact derivatives of the rigid transform):
///   r = R(theta)(X - c),  x = c + d + r,  v = d' + omega e_z x r,  a = d'' + alpha e_z x r -
///   omega^2 r.
struct NodeState {
  Vec2 x, v, a;
};
NodeState rigid_node_state(const RigidKinematics& k, const Vec2& pivot, const Vec2& X);

} // namespace fsi::erp
