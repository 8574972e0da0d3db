#include "geometry_erp/lattice_spectrum.hpp"

#include "lattice_points.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

namespace fsi::erp {

namespace {

/// A lattice point within r_e: its index m (x_j = l0 m) and w(|x_j|).
template <int D> struct WeightedPoint {
  std::array<int, D> m;
  double w;
};

template <int D>
std::vector<WeightedPoint<D>> weighted_points(double l0, double r_e, const WeightFunction& w) {
  std::vector<WeightedPoint<D>> points;
  for_each_lattice_point<D>(l0, r_e, [&](const std::array<int, D>& m, double r) {
    if (r < r_e) points.push_back({m, w(r)});
  });
  return points;
}

/// k . x_j / pi for k = (pi/l0) kappa.
template <int D> double phase(const std::array<double, D>& kappa, const std::array<int, D>& m) {
  double s = 0.0;
  for (std::size_t a = 0; a < D; ++a) s += kappa[a] * m[a];
  return s;
}

} // namespace

template <int D> double lattice_laplacian_peak(double l0, double r_e, const WeightFunction& w) {
  const std::vector<WeightedPoint<D>> points = weighted_points<D>(l0, r_e, w);
  const auto symbol = [&](const std::array<double, D>& kappa) {
    double s = 0.0;
    for (const WeightedPoint<D>& p : points)
      s += p.w * (1.0 - std::cos(std::numbers::pi * phase<D>(kappa, p.m)));
    return s;
  };
  // kappa = k l0 / pi on a grid of (M + 1)^D points of [0, 1]^D ...
  constexpr int M = 8;
  std::array<double, D> best{};
  double peak = 0.0;
  int cells = 1;
  for (int a = 0; a < D; ++a) cells *= M + 1;
  for (int code = 0; code < cells; ++code) {
    std::array<double, D> kappa;
    for (int a = 0, c = code; a < D; ++a, c /= M + 1)
      kappa[static_cast<std::size_t>(a)] = static_cast<double>(c % (M + 1)) / M;
    if (const double s = symbol(kappa); s > peak) peak = s, best = kappa;
  }
  // ... then a compass search from the best point, its step halved down to 1e-8.
  for (double h = 0.5 / M; h > 1e-8; h *= 0.5) {
    for (bool moved = true; moved;) {
      moved = false;
      for (std::size_t a = 0; a < D; ++a)
        for (const double step : {-h, h}) {
          std::array<double, D> trial = best;
          trial[a] = std::clamp(trial[a] + step, 0.0, 1.0);
          if (const double s = symbol(trial); s > peak) peak = s, best = trial, moved = true;
        }
    }
  }
  return peak;
}

template <int D> double lattice_closing_peak(double l0, double r_e, const WeightFunction& w) {
  const std::vector<WeightedPoint<D>> points = weighted_points<D>(l0, r_e, w);
  using Matrix = Eigen::Matrix<double, D, D>;
  using Vector = Eigen::Matrix<double, D, 1>;
  double peak = 0.0;
  for (int flip = 1; flip < (1 << D); ++flip) { // kappa in {0, 1}^D, not 0
    Matrix T = Matrix::Zero();
    for (const WeightedPoint<D>& p : points) {
      int parity = 0;
      for (int a = 0; a < D; ++a) parity += (flip >> a & 1) * p.m[static_cast<std::size_t>(a)];
      if (parity % 2 == 0) continue; // k . x_j an even multiple of pi: the pair moves as one
      Vector e;
      for (int a = 0; a < D; ++a) e[a] = p.m[static_cast<std::size_t>(a)];
      e.normalize();
      T += p.w * e * e.transpose();
    }
    peak = std::max(peak, Eigen::SelfAdjointEigenSolver<Matrix>(T).eigenvalues().maxCoeff());
  }
  return peak;
}

template double lattice_laplacian_peak<2>(double, double, const WeightFunction&);
template double lattice_laplacian_peak<3>(double, double, const WeightFunction&);
template double lattice_closing_peak<2>(double, double, const WeightFunction&);
template double lattice_closing_peak<3>(double, double, const WeightFunction&);

} // namespace fsi::erp
