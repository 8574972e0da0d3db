#include "geometry_erp/cubic_spline.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace fsi::erp {

CubicSpline::CubicSpline(std::vector<double> t, std::vector<double> y)
    : t_(std::move(t)), y_(std::move(y)), m_(t_.size(), 0.0) {
  const std::size_t n = t_.size();
  assert(n >= 2 && y_.size() == n);
  // Tridiagonal system for the interior second derivatives (Thomas algorithm), m_0 = m_N = 0.
  std::vector<double> c(n, 0.0), d(n, 0.0);
  for (std::size_t k = 1; k + 1 < n; ++k) {
    const double h0 = t_[k] - t_[k - 1], h1 = t_[k + 1] - t_[k];
    assert(h0 > 0.0 && h1 > 0.0);
    const double rhs = 6.0 * ((y_[k + 1] - y_[k]) / h1 - (y_[k] - y_[k - 1]) / h0);
    const double diag = 2.0 * (h0 + h1) - h0 * c[k - 1];
    c[k] = h1 / diag;
    d[k] = (rhs - h0 * d[k - 1]) / diag;
  }
  for (std::size_t k = n - 1; k-- > 1;) m_[k] = d[k] - c[k] * m_[k + 1];

  const double h = (t_.back() - t_.front()) / static_cast<double>(n - 1);
  uniform_ = true;
  for (std::size_t k = 1; k < n; ++k)
    if (std::abs(t_[k] - t_[k - 1] - h) > 1e-12 * h) uniform_ = false;
}

SplineValue CubicSpline::operator()(double t) const {
  if (t <= t_.front()) return {y_.front(), 0.0, 0.0};
  if (t >= t_.back()) return {y_.back(), 0.0, 0.0};
  const std::size_t last = t_.size() - 2;
  std::size_t k;
  if (uniform_) {
    const double h = (t_.back() - t_.front()) / static_cast<double>(last + 1);
    k = std::min(static_cast<std::size_t>((t - t_.front()) / h), last);
    if (t < t_[k] && k > 0) --k; // division rounding at a knot
  } else {
    k = static_cast<std::size_t>(std::upper_bound(t_.begin(), t_.end(), t) - t_.begin()) - 1;
    k = std::min(k, last);
  }
  const double h = t_[k + 1] - t_[k];
  const double a = (t_[k + 1] - t) / h, b = (t - t_[k]) / h;
  const double m0 = m_[k], m1 = m_[k + 1];
  const double y =
      a * y_[k] + b * y_[k + 1] + ((a * a * a - a) * m0 + (b * b * b - b) * m1) * h * h / 6.0;
  const double dy =
      (y_[k + 1] - y_[k]) / h + ((1.0 - 3.0 * a * a) * m0 + (3.0 * b * b - 1.0) * m1) * h / 6.0;
  const double d2y = a * m0 + b * m1;
  return {y, dy, d2y};
}

} // namespace fsi::erp
