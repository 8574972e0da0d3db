// A 3-D flow with a closed-form solution (issue 45): the Arnold-Beltrami-Childress (ABC) flow in a
// periodic cube, u = (A sin kz + C cos ky, B sin kx + A cos kz, C sin ky + B cos kx). Its
// vorticity is k u (a Beltrami field), so u . grad u = grad |u|^2 / 2 and the Navier-Stokes
// solution is u(x, t) = e^{-nu k^2 t} u(x, 0), p = -rho |u|^2 / 2: a 3-D Taylor-Green-like decay
// in every direction (docs/fluid_sph.md, "3-D").
#include "fluid_sph/sph_fluid.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

using namespace fsi;

namespace {

constexpr double kL = 1.0, kNu = 0.05; // cube side, m; nu, m^2/s (Re = U L / nu = 20)
const double kK = 2.0 * std::numbers::pi / kL;

/// The ABC field with A = B = C = 1 / sqrt(3) (mean |u|^2 = 1) at x, time t.
Vec3 abc(const Vec3& x, double t) {
  const double a = std::exp(-kNu * kK * kK * t) / std::sqrt(3.0);
  const double sx = std::sin(kK * x.x()), sy = std::sin(kK * x.y()), sz = std::sin(kK * x.z());
  const double cx = std::cos(kK * x.x()), cy = std::cos(kK * x.y()), cz = std::cos(kK * x.z());
  return a * Vec3(sz + cy, sx + cz, sy + cx);
}

/// The kinetic energy's decay rate -d ln E / dt (least squares over t in [0.1, 0.4]) at m^3
/// particles; exact: 2 nu k^2.
double abc_rate(int m, sph::Correction corr) {
  sph::SphOptions3 o;
  o.rho0 = 1.0, o.dp = kL / m, o.c0 = 10.0 * std::sqrt(2.0), o.u_ref = std::sqrt(2.0);
  o.viscosity = kNu, o.correction = corr, o.wkgc_alpha = 0.0;
  o.free_surface = false, o.transport_velocity = true;
  o.domain_min = Vec3::Zero(), o.domain_max = Vec3::Constant(kL);
  o.periodic_x = o.periodic_y = o.periodic_z = true;
  const auto x = sph::fill_box(Vec3::Zero(), Vec3::Constant(kL), o.dp);
  sph::SphFluid3 f(o, x);
  std::vector<Vec3> v(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) v[i] = abc(x[i], 0.0);
  f.set_velocities(v);
  double st = 0, sl = 0, stt = 0, stl = 0;
  const int n = 16;
  for (int s = 0; s < n; ++s) {
    const double t = 0.1 + 0.3 * s / (n - 1.0); // nu k^2 t up to 0.79: E falls to 0.2
    f.advance_to(t);
    const double l = std::log(f.kinetic_energy());
    st += t, sl += l, stt += t * t, stl += t * l;
  }
  return -(n * stl - st * sl) / (n * stt - st * st);
}

} // namespace

TEST_CASE("sph 3-D: ABC flow in a periodic cube at 10^3, 16^3 particles: the energy's decay "
          "rate converges, rkgc closer than none",
          "[sph][3d][slow]") {
  const double exact = 2.0 * kNu * kK * kK;
  double last_rkgc = 1.0;
  for (int m : {10, 16}) {
    const double r_rkgc = abc_rate(m, sph::Correction::rkgc);
    const double r_none = abc_rate(m, sph::Correction::none);
    const double e_rkgc = std::abs(r_rkgc / exact - 1.0), e_none = std::abs(r_none / exact - 1.0);
    INFO("m = " << m << ": rate rkgc " << r_rkgc << ", none " << r_none << ", exact " << exact);
    CHECK(e_rkgc < e_none);
    CHECK(e_rkgc < last_rkgc);
    last_rkgc = e_rkgc;
  }
  CHECK(last_rkgc < 0.05);
}
