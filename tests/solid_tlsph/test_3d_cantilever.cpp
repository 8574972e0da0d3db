// A 3-D TL-SPH cantilever (library defaults: quadratic correction, hourglass control, the clamp
// at its face x = 0) against Timoshenko beam theory: the static deflection of the end section
// under an end load (dynamic relaxation) and the first bending frequency of a free vibration.
// L = 1 m, square section H = 0.1 m, steel with nu = 0 (no Poisson restraint at the clamp, the
// shear coefficient of a square section is then 5/6 exactly; Cowper's 10 (1 + nu) / (12 + 11 nu)).
#include <catch2/catch.hpp>

#include <Eigen/Eigenvalues>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "solid_tlsph/solid.hpp"

namespace {

using fsi::Vec3;
using namespace fsi::tlsph;

struct Beam3 {
  double L = 1.0, H = 0.1, E = 2.1e11, nu = 0.0, rho = 7800.0;
  int layers = 4; ///< particles through the thickness (both directions)
  double dp() const { return H / layers; }
  double A() const { return H * H; }
  double I() const { return H * H * H * H / 12.0; }
  double kGA() const { return 10.0 * (1.0 + nu) / (12.0 + 11.0 * nu) * E / (2.0 + 2.0 * nu) * A(); }
  /// Euler–Bernoulli first bending frequency [rad/s].
  double omega_eb() const {
    const double kL = 1.8751040687119611;
    return kL * kL / (L * L) * std::sqrt(E * I() / (rho * A()));
  }
  /// Timoshenko deflection at x under an end load P: P x^2 (3L - x) / (6EI) + P x / (kGA).
  double deflection(double P, double x) const {
    return P * x * x * (3.0 * L - x) / (6.0 * E * I()) + P * x / kGA();
  }
  /// Timoshenko first frequency (shear and rotary inertia) [rad/s]: 400 two-node elements
  /// (linear w and theta, one-point shear: no locking; consistent mass), clamped at x = 0.
  double omega_timoshenko() const {
    const int n = 400, dofs = 2 * n; // (w, theta) at nodes 1..n
    const double le = L / n;
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(dofs, dofs), M = K;
    for (int e = 0; e < n; ++e) {
      Eigen::Matrix4d k = Eigen::Matrix4d::Zero(), m = Eigen::Matrix4d::Zero();
      const Eigen::Vector4d bb(0.0, -1.0 / le, 0.0, 1.0 / le);   // theta'
      const Eigen::Vector4d bs(-1.0 / le, -0.5, 1.0 / le, -0.5); // gamma = w' - theta
      k = E * I() * le * bb * bb.transpose() + kGA() * le * bs * bs.transpose();
      for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b) {
          const double c = le / 6.0 * (a == b ? 2.0 : 1.0);
          m(2 * a, 2 * b) = rho * A() * c, m(2 * a + 1, 2 * b + 1) = rho * I() * c;
        }
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) {
          const int ra = 2 * e + a - 2, rb = 2 * e + b - 2; // node e's dofs start at 2 (e - 1)
          if (ra >= 0 && rb >= 0) K(ra, rb) += k(a, b), M(ra, rb) += m(a, b);
        }
    }
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(K, M,
                                                                        Eigen::EigenvaluesOnly);
    return std::sqrt(eig.eigenvalues()(0));
  }
};

TlsphSolid3 make_beam(const Beam3& b, double mass_damping) {
  TlsphOptions3 o;
  o.dp = b.dp();
  o.material = {b.E, b.nu, b.rho, fsi::materials::PlaneModel::plane_strain}; // plane: unused
  o.mass_damping = mass_damping;
  Clamp3 clamp;
  clamp.contains = [](const Vec3& X) { return X.x() < 0.0; };
  o.clamps.push_back(clamp);
  const double clamp_depth = 4.0 * b.dp();
  return TlsphSolid3(fill_box(Vec3(-clamp_depth, 0.0, 0.0), Vec3(b.L, b.H, b.H), b.dp()), o);
}

/// The particles of the end layer x = L - dp/2.
std::vector<std::size_t> end_layer(const TlsphSolid3& s, const Beam3& b) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < s.size(); ++i)
    if (std::abs(s.reference_position(i).x() - (b.L - 0.5 * b.dp())) < 1e-9) out.push_back(i);
  return out;
}

double mean_w(const TlsphSolid3& s, const std::vector<std::size_t>& layer) {
  double w = 0.0;
  for (const auto i : layer) w += s.displacement(i).y();
  return w / static_cast<double>(layer.size());
}

struct Figures {
  double w, w_ref, omega, omega_ref, seconds;
  std::size_t particles;
};

/// Static end-section deflection under P (mass damping 2 omega, 12 / omega: critically damped
/// first mode, residual ~ 13 e^-12) and the period of a free vibration started with the
/// Euler–Bernoulli mode's velocity (two zero crossings of the end section, linear interpolation
/// between chunks of T / 400).
Figures cantilever(const Beam3& b) {
  const auto start = std::chrono::steady_clock::now();
  const double P = 1.0e3, omega_eb = b.omega_eb(), x_end = b.L - 0.5 * b.dp();
  Figures f{};
  {
    TlsphSolid3 s = make_beam(b, 2.0 * omega_eb);
    const auto layer = end_layer(s, b);
    std::vector<Vec3> load(s.size(), Vec3::Zero());
    for (const auto i : layer) load[i] = Vec3(0.0, -P / static_cast<double>(layer.size()), 0.0);
    s.set_external_forces(load);
    s.advance(0.0, 12.0 / omega_eb);
    f.w = -mean_w(s, layer), f.w_ref = b.deflection(P, x_end), f.particles = s.size();
  }
  {
    TlsphSolid3 s = make_beam(b, 0.0);
    const auto layer = end_layer(s, b);
    const double kL = 1.8751040687119611, Mm = std::sin(kL) + std::sinh(kL),
                 Nm = std::cos(kL) + std::cosh(kL);
    auto mode = [&](double x) { // clamped-free Euler–Bernoulli mode 1, 2 at the free end
      const double k = kL / b.L;
      return Mm * (std::cos(k * x) - std::cosh(k * x)) - Nm * (std::sin(k * x) - std::sinh(k * x));
    };
    const double scale = 0.01 / std::abs(mode(b.L)); // tip velocity 0.01 m/s
    std::vector<Vec3> v(s.size(), Vec3::Zero());
    for (std::size_t i = 0; i < s.size(); ++i)
      if (!s.clamped(i)) v[i] = Vec3(0.0, scale * std::abs(mode(s.reference_position(i).x())), 0.0);
    s.set_velocities(v);
    const double chunk = 2.0 * std::numbers::pi / omega_eb / 400.0;
    std::vector<double> crossings;
    double w_last = mean_w(s, layer);
    while (crossings.size() < 2 && s.time() < 3.0 * 2.0 * std::numbers::pi / omega_eb) {
      const double t0 = s.time();
      s.advance(t0, chunk);
      const double w = mean_w(s, layer);
      if (t0 > 0.0 && (w_last > 0.0) != (w > 0.0))
        crossings.push_back(t0 + chunk * w_last / (w_last - w));
      w_last = w;
    }
    REQUIRE(crossings.size() == 2);
    f.omega = 2.0 * std::numbers::pi / crossings[1]; // w = a sin(omega t): 0 at T/2 and T
  }
  f.omega_ref = b.omega_timoshenko();
  f.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("tlsph 3-D cantilever H/dp = %d: %zu particles, w = %.6e m (Timoshenko %.6e, "
              "%+.3f %%), omega_1 = %.3f rad/s (Timoshenko %.3f, %+.3f %%; Euler-Bernoulli "
              "%.3f), %.1f s\n",
              b.layers, f.particles, f.w, f.w_ref, 100.0 * (f.w / f.w_ref - 1.0), f.omega,
              f.omega_ref, 100.0 * (f.omega / f.omega_ref - 1.0), omega_eb, f.seconds);
  return f;
}

} // namespace

TEST_CASE("tlsph 3-D: the Timoshenko reference tends to Euler–Bernoulli for a slender beam",
          "[solid_tlsph][3d]") {
  Beam3 b;
  b.L = 10.0; // L / H = 100: shear and rotary inertia below 1e-3
  CHECK_THAT(b.omega_timoshenko() / b.omega_eb(), Catch::Matchers::WithinAbs(1.0, 1e-3));
  b.L = 1.0; // L / H = 10: softer, by about 1 %
  const double r = b.omega_timoshenko() / b.omega_eb();
  CHECK(r < 0.995);
  CHECK(r > 0.98);
}

TEST_CASE("tlsph 3-D cantilever: deflection and first frequency within 2 % of Timoshenko",
          "[solid_tlsph][3d][slow]") {
  std::vector<Figures> runs;
  for (const int layers : {4, 6}) {
    Beam3 b;
    b.layers = layers;
    runs.push_back(cantilever(b));
  }
  const Figures& fine = runs.back();
  CHECK_THAT(fine.w / fine.w_ref, Catch::Matchers::WithinAbs(1.0, 0.02));
  CHECK_THAT(fine.omega / fine.omega_ref, Catch::Matchers::WithinAbs(1.0, 0.02));
}
