#include "geometry_erp/motion.hpp"

#include "geometry_erp/csv_table.hpp"

#include <cmath>
#include <numbers>

namespace fsi::erp {

namespace {
/// s(t) = sin(w t + phase) and its first two derivatives.
SplineValue sinusoid(double period, double phase, double t) {
  const double w = 2.0 * std::numbers::pi / period;
  const double s = std::sin(w * t + phase), c = std::cos(w * t + phase);
  return {s, w * c, -w * w * s};
}
} // namespace

SinusoidTranslation::SinusoidTranslation(Vec2 amplitude, double period, double phase)
    : amplitude_(amplitude), period_(period), phase_(phase) {}

RigidKinematics SinusoidTranslation::at(double t) const {
  const SplineValue s = sinusoid(period_, phase_, t);
  RigidKinematics k;
  k.d = s.y * amplitude_;
  k.d_dot = s.dy * amplitude_;
  k.d_ddot = s.d2y * amplitude_;
  return k;
}

SinusoidRotation::SinusoidRotation(double amplitude, double period, double phase)
    : amplitude_(amplitude), period_(period), phase_(phase) {}

RigidKinematics SinusoidRotation::at(double t) const {
  const SplineValue s = sinusoid(period_, phase_, t);
  RigidKinematics k;
  k.theta = amplitude_ * s.y;
  k.omega = amplitude_ * s.dy;
  k.alpha = amplitude_ * s.d2y;
  return k;
}

namespace {
std::vector<double> scaled(std::vector<double> v, double scale) {
  for (double& x : v) x *= scale;
  return v;
}
} // namespace

TableTranslation::TableTranslation(const std::string& csv_path, double scale) {
  const CsvTable table = read_csv_table(csv_path, 3);
  dx_ = CubicSpline(table.columns[0], scaled(table.columns[1], scale));
  dy_ = CubicSpline(table.columns[0], scaled(table.columns[2], scale));
}

TableTranslation::TableTranslation(const std::string& csv_path, const Vec2& direction) {
  const CsvTable table = read_csv_table(csv_path, 2);
  dx_ = CubicSpline(table.columns[0], scaled(table.columns[1], direction.x()));
  dy_ = CubicSpline(table.columns[0], scaled(table.columns[1], direction.y()));
}

RigidKinematics TableTranslation::at(double t) const {
  const SplineValue x = dx_(t), y = dy_(t);
  RigidKinematics k;
  k.d = {x.y, y.y};
  k.d_dot = {x.dy, y.dy};
  k.d_ddot = {x.d2y, y.d2y};
  return k;
}

TableRotation::TableRotation(const std::string& csv_path, double scale) {
  const CsvTable table = read_csv_table(csv_path, 2);
  theta_ = CubicSpline(table.columns[0], scaled(table.columns[1], scale));
}

RigidKinematics TableRotation::at(double t) const {
  const SplineValue s = theta_(t);
  RigidKinematics k;
  k.theta = s.y;
  k.omega = s.dy;
  k.alpha = s.d2y;
  return k;
}

SumMotion::SumMotion(std::vector<std::shared_ptr<const Motion>> parts) : parts_(std::move(parts)) {}

RigidKinematics SumMotion::at(double t) const {
  RigidKinematics sum;
  for (const auto& part : parts_) {
    const RigidKinematics k = part->at(t);
    sum.d += k.d;
    sum.d_dot += k.d_dot;
    sum.d_ddot += k.d_ddot;
    sum.theta += k.theta;
    sum.omega += k.omega;
    sum.alpha += k.alpha;
  }
  return sum;
}

NodeState rigid_node_state(const RigidKinematics& k, const Vec2& pivot, const Vec2& X) {
  const double c = std::cos(k.theta), s = std::sin(k.theta);
  const Vec2 X_c = X - pivot;
  const Vec2 r(c * X_c.x() - s * X_c.y(), s * X_c.x() + c * X_c.y());
  const Vec2 ez_cross_r(-r.y(), r.x());
  return {pivot + k.d + r, k.d_dot + k.omega * ez_cross_r,
          k.d_ddot + k.alpha * ez_cross_r - k.omega * k.omega * r};
}

} // namespace fsi::erp
