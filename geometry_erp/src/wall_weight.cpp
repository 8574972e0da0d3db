#include "geometry_erp/wall_weight.hpp"

#include "lattice_points.hpp"

#include <cmath>
#include <vector>

namespace fsi::erp {

template <int D> double wall_weight_sum(double r, double l0, double r_e, const WeightFunction& w) {
  const int n = reach(l0, r_e);
  double z = 0.0;
  for (int m = 0; r + 0.5 * l0 + m * l0 < r_e; ++m) {
    const double dy = r + 0.5 * l0 + m * l0; // particle at y = r, virtual row at -l0/2 - m l0
    if constexpr (D == 2) {
      for (int i = -n; i <= n; ++i) z += w(std::hypot(i * l0, dy));
    } else { // columns (i l0, j l0) of the virtual layer, x fastest
      for (int j = -n; j <= n; ++j)
        for (int i = -n; i <= n; ++i) z += w(std::hypot(i * l0, j * l0, dy));
    }
  }
  return z;
}

double corner_weight_sum(double a, double b, double l0, double r_e, const WeightFunction& w) {
  double q = 0.0;
  for (int m = 0; a + 0.5 * l0 + m * l0 < r_e; ++m)
    for (int k = 0; b + 0.5 * l0 + k * l0 < r_e; ++k)
      q += w(std::hypot(a + 0.5 * l0 + m * l0, b + 0.5 * l0 + k * l0));
  return q;
}

double edge_weight_sum3(double a, double b, double l0, double r_e, const particles::MpsWeight& w) {
  const int n = reach(l0, r_e);
  double q = 0.0;
  for (int m = 0; a + 0.5 * l0 + m * l0 < r_e; ++m)
    for (int k = 0; b + 0.5 * l0 + k * l0 < r_e; ++k)
      for (int j = -n; j <= n; ++j)
        q += w(std::hypot(a + 0.5 * l0 + m * l0, b + 0.5 * l0 + k * l0, j * l0));
  return q;
}

double corner_weight_sum3(double a, double b, double c, double l0, double r_e,
                          const particles::MpsWeight& w) {
  double o = 0.0;
  for (int m = 0; a + 0.5 * l0 + m * l0 < r_e; ++m)
    for (int k = 0; b + 0.5 * l0 + k * l0 < r_e; ++k)
      for (int l = 0; c + 0.5 * l0 + l * l0 < r_e; ++l)
        o += w(std::hypot(a + 0.5 * l0 + m * l0, b + 0.5 * l0 + k * l0, c + 0.5 * l0 + l * l0));
  return o;
}

template <int D>
double wall_gradient_sum(double r, double l0, double r_e, const WeightFunction& w) {
  const int n = reach(l0, r_e);
  double g = 0.0;
  for (int m = 0; r + 0.5 * l0 + m * l0 < r_e; ++m) {
    const double dy = r + 0.5 * l0 + m * l0;
    if constexpr (D == 2) {
      for (int i = -n; i <= n; ++i) {
        const double rho2 = i * l0 * i * l0 + dy * dy;
        g += dy / rho2 * w(std::sqrt(rho2));
      }
    } else {
      for (int j = -n; j <= n; ++j)
        for (int i = -n; i <= n; ++i) {
          const double rho2 = i * l0 * i * l0 + j * l0 * j * l0 + dy * dy;
          g += dy / rho2 * w(std::sqrt(rho2));
        }
    }
  }
  return g;
}

template double wall_weight_sum<2>(double, double, double, const WeightFunction&);
template double wall_weight_sum<3>(double, double, double, const WeightFunction&);
template double wall_gradient_sum<2>(double, double, double, const WeightFunction&);
template double wall_gradient_sum<3>(double, double, double, const WeightFunction&);

Vec2 corner_gradient_sum(double a, double b, double l0, double r_e, const WeightFunction& w) {
  Vec2 g = Vec2::Zero();
  for (int m = 0; a + 0.5 * l0 + m * l0 < r_e; ++m)
    for (int k = 0; b + 0.5 * l0 + k * l0 < r_e; ++k) {
      const double da = a + 0.5 * l0 + m * l0, db = b + 0.5 * l0 + k * l0;
      const double rho2 = da * da + db * db;
      g += Vec2(da, db) * (w(std::sqrt(rho2)) / rho2);
    }
  return g;
}

template <int D> double lattice_n0(double l0, double r_e, const WeightFunction& w) {
  double n0 = 0.0;
  for_each_lattice_point<D>(l0, r_e, [&](const auto&, double r) { n0 += w(r); }); // eq. 9
  return n0;
}

template <int D> double lattice_lambda0(double l0, double r_e, const WeightFunction& w) {
  double sum_r2w = 0.0;
  for_each_lattice_point<D>(l0, r_e, [&](const auto&, double r) { sum_r2w += r * r * w(r); });
  return sum_r2w / lattice_n0<D>(l0, r_e, w); // eq. 12
}

template double lattice_n0<2>(double, double, const WeightFunction&);
template double lattice_n0<3>(double, double, const WeightFunction&);
template double lattice_lambda0<2>(double, double, const WeightFunction&);
template double lattice_lambda0<3>(double, double, const WeightFunction&);

template <int D>
BasicWallWeightTable<D>::BasicWallWeightTable(double l0, double r_e, const WeightFunction& w,
                                              int min_intervals)
    : l0_(l0), r_e_(r_e), r_zero_(r_e - 0.5 * l0) {
  // Intervals per half spacing, so that l0/2 + k l0 fall on knots.
  const int M = std::max(1, static_cast<int>(std::ceil(min_intervals * 0.5 * l0 / r_e)));
  dr_ = 0.5 * l0 / M;
  const int knots = std::max(2, static_cast<int>(std::ceil(r_zero_ / dr_)) + 1);
  std::vector<double> r(static_cast<std::size_t>(knots)), z(r.size());
  for (int k = 0; k < knots; ++k) {
    r[static_cast<std::size_t>(k)] = k * dr_;
    z[static_cast<std::size_t>(k)] = wall_weight_sum<D>(k * dr_, l0, r_e, w);
  }
  z_ = CubicSpline(std::move(r), std::move(z));
}

template class BasicWallWeightTable<2>;
template class BasicWallWeightTable<3>;

} // namespace fsi::erp
