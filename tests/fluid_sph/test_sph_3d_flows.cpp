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

/// The relative L2 error of the particles' velocities against u(x_i, t_end) at m^3 particles.
double abc_error(int m, sph::Correction corr) {
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
  const double t_end = 0.4; // nu k^2 t = 0.79: the energy falls to 0.21
  f.advance_to(t_end);
  const auto& p = f.particles();
  double e2 = 0.0, u2 = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3 exact = abc({p.x[0][i], p.x[1][i], p.x[2][i]}, t_end);
    e2 += (Vec3(p.v[0][i], p.v[1][i], p.v[2][i]) - exact).squaredNorm();
    u2 += exact.squaredNorm();
  }
  return std::sqrt(e2 / u2);
}

} // namespace

TEST_CASE("sph 3-D: ABC flow in a periodic cube at 10^3, 16^3 particles: rkgc converges and "
          "is closer than none",
          "[sph][3d][slow]") {
  double last_rkgc = 1.0;
  for (int m : {10, 16}) {
    const double e_rkgc = abc_error(m, sph::Correction::rkgc);
    const double e_none = abc_error(m, sph::Correction::none);
    INFO("m = " << m << ": relative L2 velocity error rkgc " << e_rkgc << ", none " << e_none);
    CHECK(e_rkgc < e_none);
    CHECK(e_rkgc < last_rkgc);
    last_rkgc = e_rkgc;
  }
  CHECK(last_rkgc < 0.05);
}
