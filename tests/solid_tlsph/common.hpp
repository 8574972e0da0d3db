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
  GradientCorrection correction = TlsphOptions{}.gradient_correction; ///< the library default
  bool odd_image = Clamp{}.odd_image; ///< the library default: u = 0 on the clamp face x = 0
  double dp() const { return H / layers; }
  /// The paper's form: eqs. 13-14 (GradientCorrection::linear) and the clamped particles held.
  Beam paper() const {
    Beam b = *this;
    b.correction = GradientCorrection::linear, b.odd_image = false;
    return b;
  }
  fsi::materials::MaterialOptions material() const { return {E, nu, rho, plane}; }
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
  o.material = b.material();
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

/// Displacement of the mid-height point of the free end, (L, y0 + H/2), the point structure_fem's
/// elastica test measures: x_p + F_p (X - X_p) from each of the one or two tip particles
/// nearest mid-height (the interface nodes' formula), averaged.
inline Vec2 end_face_displacement(const TlsphSolid& s, const Beam& b) {
  Vec2 u = Vec2::Zero();
  int n = 0;
  const Vec2 X(b.L, b.y0 + 0.5 * b.H);
  for (const auto i : tip_column(s, b))
    if (std::abs(s.reference_position(i).y() - X.y()) < 0.51 * b.dp() + 1e-12)
      u += s.position(i) + s.deformation_gradient(i) * (X - s.reference_position(i)) - X, ++n;
  return u / n;
}

/// Timoshenko cantilever under an end load P: deflection at x,
/// w(x) = P x^2 (3L - x) / (6 E' I) + P x / (kappa G A), kappa = 5/6.
inline double timoshenko_deflection(const Beam& b, double P, double x) {
  const double G = b.E / (2.0 * (1.0 + b.nu));
  return P * x * x * (3.0 * b.L - x) / (6.0 * b.E_bending() * b.I()) +
         P * x / (5.0 / 6.0 * G * b.H);
}

/// Elastica of a cantilever (length 1) under a dead end load with k = P L^2 / EI, at arc length
/// s; y downwards positive as deflection. theta' = m, m' = -k x', theta(0) = 0, m(1) = 0
/// (shooting on m(0), RK4, bisection). Euler's elastica (inextensible, shear-rigid) by default;
/// `axial` = EI / (EA L^2) and `shear` = EI / (kappa G A L^2) make it Reissner's (stretch
/// eps = k sin(theta) axial, shear strain gamma = k cos(theta) shear):
/// x' = (1 + eps) cos(theta) - gamma sin(theta), y' = (1 + eps) sin(theta) + gamma cos(theta).
inline Vec2 elastica_point(double k, double s, double axial = 0.0, double shear = 0.0) {
  using State = std::array<double, 4>; // theta, m, x, y
  auto f = [&](const State& z) {
    const double c = std::cos(z[0]), sn = std::sin(z[0]);
    const double eps = k * sn * axial, gamma = k * c * shear;
    const double dx = (1.0 + eps) * c - gamma * sn, dy = (1.0 + eps) * sn + gamma * c;
    return State{z[1], -k * dx, dx, dy};
  };
  auto step = [&](const State& z, double hs) {
    auto add = [](const State& a, const State& b, double w) {
      return State{a[0] + w * b[0], a[1] + w * b[1], a[2] + w * b[2], a[3] + w * b[3]};
    };
    const State k1 = f(z), k2 = f(add(z, k1, 0.5 * hs)), k3 = f(add(z, k2, 0.5 * hs)),
                k4 = f(add(z, k3, hs));
    State out = z;
    for (int c = 0; c < 4; ++c) out[c] += hs / 6.0 * (k1[c] + 2 * k2[c] + 2 * k3[c] + k4[c]);
    return out;
  };
  const int n = 20000;
  auto integrate = [&](double m0, double s_end) {
    State z{0.0, m0, 0.0, 0.0};
    const int full = static_cast<int>(std::floor(s_end * n + 1e-9));
    for (int i = 0; i < full; ++i) z = step(z, 1.0 / n);
    if (s_end - full / static_cast<double>(n) > 1e-15) z = step(z, s_end - full / double(n));
    return z;
  };
  double lo = 0.0, hi = 2.0 * k; // m(1) < 0 at m0 = 0, > 0 at m0 = 2k
  for (int it = 0; it < 100; ++it) {
    const double mid = 0.5 * (lo + hi);
    (integrate(mid, 1.0)[1] < 0.0 ? lo : hi) = mid;
  }
  const State z = integrate(0.5 * (lo + hi), s);
  return {z[2], z[3]};
}

/// The patch tests' linear displacement field u = A X + c (A not symmetric, |A| ~ 0.02).
struct LinearField {
  fsi::Mat2 A = (fsi::Mat2() << 0.013, -0.021, 0.007, 0.017).finished();
  Vec2 c{0.3, -0.2};
  Vec2 at(const Vec2& X) const { return A * X + c; }
  /// Moves every particle of s to X0 + u(X0).
  void apply(TlsphSolid& s) const {
    std::vector<Vec2> x(s.size());
    for (std::size_t i = 0; i < s.size(); ++i)
      x[i] = s.reference_position(i) + at(s.reference_position(i));
    s.set_positions(x);
  }
};

/// dPi/dx_k of the strain energy at positions x by a central difference (step 1e-7).
inline Vec2 strain_energy_gradient(TlsphSolid& s, const std::vector<Vec2>& x, std::size_t k) {
  const double d = 1e-7;
  Vec2 grad;
  for (int c = 0; c < 2; ++c) {
    auto xp = x, xm = x;
    xp[k][c] += d, xm[k][c] -= d;
    s.set_positions(xp);
    const double ep = s.energies().strain;
    s.set_positions(xm);
    grad[c] = (ep - s.energies().strain) / (2.0 * d);
  }
  return grad;
}

/// First clamped-free mode shape f(x) (Gray, Monaghan & Swift 2001), kL = 1.875.
inline double mode_shape(double x, double L) {
  const double kL = 1.8751040687119611, k = kL / L;
  const double M = std::sin(kL) + std::sinh(kL), N = std::cos(kL) + std::cosh(kL);
  return M * (std::cos(k * x) - std::cosh(k * x)) - N * (std::sin(k * x) - std::sinh(k * x));
}

/// Dynamic relaxation (mass damping 2 omega_1 set in the options) until `measure(s)` (a Vec2)
/// stops moving: advances in chunks of 1 / omega_1 until each component changes by less than
/// rtol of its magnitude over two consecutive chunks (critically damped, the change over a
/// chunk bounds the distance left to equilibrium). Returns the chunks taken, or -1 after
/// max_chunks without converging.
template <class Measure>
int relax_until(TlsphSolid& s, double omega1, Measure measure, double rtol, int max_chunks = 200) {
  Vec2 last = measure(s);
  int quiet = 0;
  for (int chunk = 1; chunk <= max_chunks; ++chunk) {
    s.advance(s.time(), 1.0 / omega1);
    const Vec2 now = measure(s);
    const Vec2 d = now - last;
    const bool still =
        std::abs(d.x()) <= rtol * std::abs(now.x()) && std::abs(d.y()) <= rtol * std::abs(now.y());
    quiet = still ? quiet + 1 : 0;
    if (quiet == 2) return chunk;
    last = now;
  }
  return -1;
}

/// Runs dynamic relaxation to static equilibrium: mass damping 2 omega_1 (critical for the
/// first mode; every other mode decays at least as fast), for `periods` / omega_1.
inline void relax(TlsphSolid& s, double omega1, double time_constants) {
  const double t_end = s.time() + time_constants / omega1;
  s.advance(s.time(), t_end - s.time());
}

} // namespace tlsph_test
