#pragma once
// Shared set-ups of the solid_tlsph tests: a cantilever [0, L] x [y0, y0 + H] filled at dp,
// extended by `clamp_layers` clamped layers into x < 0 (the reference code's clamp: ends
// extended 4 dp, ../shared/sph-method-notes.md), and beam-theory references.
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "solid_tlsph/solid.hpp"

namespace tlsph_test {

using fsi::Vec2;
using namespace fsi::tlsph;

struct Beam {
  double L = 1.0, H = 0.1, y0 = 0.0;
  double E = 2.1e11, nu = 0.3, rho = 7800.0;
  fsi::materials::PlaneModel plane = fsi::materials::PlaneModel::plane_strain;
  int layers = 8;            ///< particles through the thickness
  int clamp_layers = 4;      ///< clamped columns at x < 0
  double clamp_length = 0.0; ///< > 0: the clamped length instead of clamp_layers dp
  GradientCorrection correction = GradientCorrection::linear;
  bool odd_image = false; ///< the clamp imposes u = 0 on its face x = 0 (Clamp::odd_image)
  double dp() const { return H / layers; }
  double E_bending() const {
    return plane == fsi::materials::PlaneModel::plane_strain ? E / (1.0 - nu * nu) : E;
  }
  double I() const { return H * H * H / 12.0; }
  /// First bending mode of the clamped-free Euler–Bernoulli beam [rad/s].
  double omega1() const {
    const double kL = 1.8751040687119611;
    return kL * kL / (L * L) * std::sqrt(E_bending() * I() / (rho * H));
  }
};

inline TlsphOptions beam_options(const Beam& b) {
  TlsphOptions o;
  o.material.youngs_modulus = b.E;
  o.material.poisson_ratio = b.nu;
  o.material.density = b.rho;
  o.material.plane = b.plane;
  o.dp = b.dp();
  o.gradient_correction = b.correction;
  Clamp clamp;
  clamp.contains = [](const Vec2& X) { return X.x() < 0.0; };
  clamp.odd_image = b.odd_image; // face x = 0, normal (1, 0)
  o.clamps.push_back(clamp);
  o.interface_tags = {"right"};
  return o;
}

inline SolidGeometry beam_geometry(const Beam& b) {
  const double clamp = b.clamp_length > 0.0 ? b.clamp_length : b.clamp_layers * b.dp();
  return fill_rectangle({-clamp, b.y0}, {b.L, b.y0 + b.H}, b.dp());
}

/// Particles of the free-end column (x = L - dp/2).
inline std::vector<std::size_t> tip_column(const TlsphSolid& s, const Beam& b) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < s.size(); ++i)
    if (std::abs(s.reference_position(i).x() - (b.L - 0.5 * b.dp())) < 1e-9 * b.L) out.push_back(i);
  return out;
}

/// Mean displacement of the one or two particles of the tip column nearest mid-height.
inline Vec2 tip_displacement(const TlsphSolid& s, const Beam& b) {
  Vec2 u = Vec2::Zero();
  int n = 0;
  const double mid = b.y0 + 0.5 * b.H;
  for (const auto i : tip_column(s, b))
    if (std::abs(s.reference_position(i).y() - mid) < 0.51 * b.dp() + 1e-12)
      u += s.displacement(i), ++n;
  return u / n;
}

/// Timoshenko cantilever under an end load P: deflection at x,
/// w(x) = P x^2 (3L - x) / (6 E' I) + P x / (kappa G A), kappa = 5/6.
inline double timoshenko_deflection(const Beam& b, double P, double x) {
  const double G = b.E / (2.0 * (1.0 + b.nu));
  return P * x * x * (3.0 * b.L - x) / (6.0 * b.E_bending() * b.I()) +
         P * x / (5.0 / 6.0 * G * b.H);
}

/// Elastica of a cantilever (length 1) under a dead end load with k = P L^2 / EI:
/// theta'' = -k cos(theta), theta(0) = 0, theta'(1) = 0 (shooting, RK4, bisection). Returns the
/// position (x, y) of arc length s (y downwards positive as deflection).
inline Vec2 elastica_point(double k, double s) {
  const int n = 20000;
  auto integrate = [&](double c, double s_end, Vec2* at) {
    double th = 0.0, w = c, x = 0.0, y = 0.0;
    const double ds = 1.0 / n;
    auto f = [&](double t, double ww) {
      return std::array<double, 4>{ww, -k * std::cos(t), std::cos(t), std::sin(t)};
    };
    for (int i = 0; i < n; ++i) {
      if (at && (i + 1) * ds > s_end + 1e-15) {
        // final partial step to s_end
        const double hs = s_end - i * ds;
        const auto k1 = f(th, w);
        const auto k2 = f(th + 0.5 * hs * k1[0], w + 0.5 * hs * k1[1]);
        const auto k3 = f(th + 0.5 * hs * k2[0], w + 0.5 * hs * k2[1]);
        const auto k4 = f(th + hs * k3[0], w + hs * k3[1]);
        x += hs / 6.0 * (k1[2] + 2 * k2[2] + 2 * k3[2] + k4[2]);
        y += hs / 6.0 * (k1[3] + 2 * k2[3] + 2 * k3[3] + k4[3]);
        *at = {x, y};
        return w;
      }
      const auto k1 = f(th, w);
      const auto k2 = f(th + 0.5 * ds * k1[0], w + 0.5 * ds * k1[1]);
      const auto k3 = f(th + 0.5 * ds * k2[0], w + 0.5 * ds * k2[1]);
      const auto k4 = f(th + ds * k3[0], w + ds * k3[1]);
      th += ds / 6.0 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0]);
      w += ds / 6.0 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1]);
      x += ds / 6.0 * (k1[2] + 2 * k2[2] + 2 * k3[2] + k4[2]);
      y += ds / 6.0 * (k1[3] + 2 * k2[3] + 2 * k3[3] + k4[3]);
    }
    if (at) *at = {x, y};
    return w;
  };
  double lo = 0.0, hi = k;
  for (int it = 0; it < 100; ++it) {
    const double mid = 0.5 * (lo + hi);
    (integrate(mid, 2.0, nullptr) < 0.0 ? lo : hi) = mid;
  }
  Vec2 p;
  integrate(0.5 * (lo + hi), s, &p);
  return p;
}

/// First clamped-free mode shape f(x) (Gray, Monaghan & Swift 2001), kL = 1.875.
inline double mode_shape(double x, double L) {
  const double kL = 1.8751040687119611, k = kL / L;
  const double M = std::sin(kL) + std::sinh(kL), N = std::cos(kL) + std::cosh(kL);
  return M * (std::cos(k * x) - std::cosh(k * x)) - N * (std::sin(k * x) - std::sinh(k * x));
}

/// Runs dynamic relaxation to static equilibrium: mass damping 2 omega_1 (critical for the
/// first mode; every other mode decays at least as fast), for `periods` / omega_1.
inline void relax(TlsphSolid& s, double omega1, double time_constants) {
  const double t_end = s.time() + time_constants / omega1;
  s.advance(s.time(), t_end - s.time());
}

} // namespace tlsph_test
