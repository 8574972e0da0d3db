#pragma once
// Natural cubic spline through (t_k, y_k): C2, so its first and second derivatives exist
// everywhere in [t_0, t_N]; the second derivative is zero at both ends (natural end conditions).
#include <vector>

namespace fsi::erp {

struct SplineValue {
  double y;   // s(t)
  double dy;  // s'(t)
  double d2y; // s''(t)
};

class CubicSpline {
public:
  CubicSpline() = default;
  /// t strictly increasing, t.size() == y.size() >= 2 (asserted; callers validate user data).
  CubicSpline(std::vector<double> t, std::vector<double> y);

  /// Value and derivatives at t. Outside [t_0, t_N] the end value is held and both derivatives
  /// are zero.
  SplineValue operator()(double t) const;

  double t_begin() const { return t_.front(); }
  double t_end() const { return t_.back(); }

private:
  std::vector<double> t_, y_, m_; // knots, values, second derivatives at knots
  bool uniform_ = false;          // equally spaced knots: interval found by division
};

} // namespace fsi::erp
