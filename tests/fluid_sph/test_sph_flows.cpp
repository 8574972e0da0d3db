// Riemann-SPH flows with known answers: the hydrostatic tank (bottom pressure rho g H) and the
// Taylor-Green vortex (kinetic-energy decay rate 16 pi^2 nu for Re = 100).
#include "fluid_sph/sph_fluid.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

using namespace fsi;

namespace {

struct Hydrostatic {
  double bottom_pressure, expected, ke_peak, ke_end;
  std::size_t below_floor;
};

Hydrostatic hydrostatic(double dp, double H, double W, double t_end, sph::Correction corr) {
  sph::SphOptions o;
  o.rho0 = 1000.0;
  o.dp = dp;
  const double g = 9.81;
  o.c0 = 10.0 * std::sqrt(2.0 * g * H);
  o.u_ref = std::sqrt(2.0 * g * H);
  o.gravity = {0.0, -g};
  o.viscosity = 1e-6;
  o.correction = corr;
  o.wkgc_alpha = 0.3;                    // the reference code's hydrostatic value (method notes)
  o.fixed_dt = 0.5 * 0.6 * o.h() / o.c0; // the hydrostatic case runs a fixed dt (issue 18)
  o.domain_min = {-0.1, -0.1};
  o.domain_max = {W + 0.1, H + 0.3};
  const std::vector<sph::WallPolyline> tank{{{{0.0, H + 0.2}, {0.0, 0.0}, {W, 0.0}, {W, H + 0.2}}}};
  sph::SphFluid f(o, sph::fill_rectangle({0, 0}, {W, H}, dp), tank);
  Hydrostatic r{};
  const int outputs = 100;
  for (int k = 1; k <= outputs; ++k) {
    f.advance_to(t_end * k / outputs);
    const double ke = f.kinetic_energy();
    r.ke_peak = std::max(r.ke_peak, ke);
    if (k == outputs) r.ke_end = ke;
  }
  // Bottom pressure: mean over the first row's particles in the middle half of the tank, against
  // rho g (H - y) at their mean height.
  const auto& p = f.particles();
  double sp = 0.0, sy = 0.0;
  int n = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.y[i] < 0.0) ++r.below_floor;
    if (p.x[i] < 0.0 || p.x[i] > W) ++r.below_floor;
    if (p.y[i] < dp && p.x[i] > 0.25 * W && p.x[i] < 0.75 * W)
      sp += f.pressure(i), sy += p.y[i], ++n;
  }
  r.bottom_pressure = sp / n;
  r.expected = o.rho0 * g * (H - sy / n);
  return r;
}

} // namespace

TEST_CASE("sph: hydrostatic tank, bottom pressure rho g H after settling", "[sph][hydrostatic]") {
  for (auto corr : {sph::Correction::rkgc, sph::Correction::none}) {
    const auto r = hydrostatic(0.02, 0.4, 0.4, 2.0, corr);
    INFO(sph::to_string(corr) << ": bottom p " << r.bottom_pressure << ", rho g (H - y) "
                              << r.expected << ", KE peak " << r.ke_peak << " end " << r.ke_end);
    CHECK(std::abs(r.bottom_pressure / r.expected - 1.0) < 0.01);
    CHECK(r.below_floor == 0);
    CHECK(r.ke_end < 0.05 * r.ke_peak);
  }
}

namespace {

/// Taylor-Green vortex on [0, 1)^2, U = 1, Re = 100: u = -U e^{bt} cos 2 pi x sin 2 pi y,
/// v = U e^{bt} sin 2 pi x cos 2 pi y, b = -8 pi^2 nu; the kinetic energy decays as e^{2bt}.
/// Returns the measured decay rate -d ln(E)/dt (least squares over t in [0.2, 1]).
double taylor_green_rate(int m, sph::Correction corr) {
  sph::SphOptions o;
  const double U = 1.0, L = 1.0, nu = U * L / 100.0;
  o.rho0 = 1.0;
  o.dp = L / m;
  o.c0 = 10.0 * U;
  o.u_ref = U;
  o.viscosity = nu;
  o.correction = corr;
  o.wkgc_alpha = 0.0;
  o.free_surface = false;
  o.transport_velocity = true;
  o.domain_min = {0, 0};
  o.domain_max = {L, L};
  o.periodic_x = o.periodic_y = true;
  const auto x = sph::fill_rectangle({0, 0}, {L, L}, o.dp);
  sph::SphFluid f(o, x);
  std::vector<Vec2> v(x.size());
  const double k = 2.0 * std::numbers::pi / L;
  for (std::size_t i = 0; i < x.size(); ++i)
    v[i] = U * Vec2(-std::cos(k * x[i].x()) * std::sin(k * x[i].y()),
                    std::sin(k * x[i].x()) * std::cos(k * x[i].y()));
  f.set_velocities(v);
  double st = 0, sl = 0, stt = 0, stl = 0;
  int n = 0;
  for (int s = 1; s <= 40; ++s) {
    const double t = 0.2 + 0.8 * (s - 1) / 39.0;
    f.advance_to(t);
    const double l = std::log(f.kinetic_energy());
    st += t, sl += l, stt += t * t, stl += t * l, ++n;
  }
  return -(n * stl - st * sl) / (n * stt - st * st);
}

} // namespace

TEST_CASE("sph: Taylor-Green vortex decay rate, rkgc closer than none", "[sph][taylor_green]") {
  const double exact = 16.0 * std::numbers::pi * std::numbers::pi / 100.0;
  double err_rkgc = 0.0, err_none = 0.0;
  for (int m : {25, 50}) {
    const double r_rkgc = taylor_green_rate(m, sph::Correction::rkgc);
    const double r_none = taylor_green_rate(m, sph::Correction::none);
    err_rkgc = std::abs(r_rkgc / exact - 1.0);
    err_none = std::abs(r_none / exact - 1.0);
    INFO("dp = 1/" << m << ": rate rkgc " << r_rkgc << ", none " << r_none << ", exact " << exact);
    CHECK(err_rkgc < err_none);
  }
  CHECK(err_rkgc < 0.05);
}

TEST_CASE("sph: Taylor-Green vortex at dp = 1/100", "[sph][taylor_green][slow]") {
  const double exact = 16.0 * std::numbers::pi * std::numbers::pi / 100.0;
  const double r_rkgc = taylor_green_rate(100, sph::Correction::rkgc);
  const double r_none = taylor_green_rate(100, sph::Correction::none);
  INFO("dp = 1/100: rate rkgc " << r_rkgc << ", none " << r_none << ", exact " << exact);
  CHECK(std::abs(r_rkgc / exact - 1.0) < 0.05);
  CHECK(std::abs(r_rkgc / exact - 1.0) < std::abs(r_none / exact - 1.0));
}
