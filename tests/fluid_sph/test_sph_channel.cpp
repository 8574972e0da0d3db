// Channel inflow buffer (RKGC paper sec. 3.2, eqs. 25-26; the reference code's periodic channel
// with an inflow buffer): a plane Poiseuille channel, whose developed flow is known exactly.
#include "fluid_sph/sph_fluid.hpp"
#include "fsi/core/error.hpp"
#include "fsi/core/parallel.hpp"
#include "fsi/core/state_archive.hpp"
#include "same_state.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace fsi;

namespace {

/// Channel of height H between two no-slip walls, periodic in x over L, the inflow buffer at
/// 0 <= x < buffer holding the parabola of mean U0 (eq. 25). Downstream of it the developed flow
/// is plane Poiseuille flow: u(y) = 6 U0 y (H - y) / H^2 driven by dp/dx = -12 mu U0 / H^2.
sph::SphOptions channel_options(double H, double L, double dp) {
  sph::SphOptions o;
  const double U0 = 1.0;
  o.rho0 = 1.0;
  o.dp = dp;
  o.viscosity = 0.1 * U0 * H; // Re = U0 H / nu = 10
  o.c0 = 10.0 * 1.5 * U0;     // 10 U_max
  o.u_ref = 1.5 * U0;
  o.correction = sph::Correction::rkgc;
  o.wkgc_alpha = 0.0; // the reference code's FSI2 value (method notes)
  o.free_surface = false;
  o.transport_velocity = true;
  o.domain_min = {0.0, -0.5 * H};
  o.domain_max = {L, 1.5 * H};
  o.periodic_x = true;
  o.inflow.buffer = 20.0 * dp; // the reference code's 20 dp
  o.inflow.velocity = U0;
  o.inflow.ramp_time = 0.5;
  o.inflow.y_min = 0.0;
  o.inflow.y_max = H;
  return o;
}

std::vector<sph::WallPolyline> channel_walls(double H, double L) {
  return {{{{0.0, 0.0}, {L, 0.0}}}, {{{L, H}, {0.0, H}}}}; // fluid on the left of each
}

} // namespace

TEST_CASE("sph: the inflow profile of eqs. 25-26 and its option checks", "[sph][inflow]") {
  sph::Inflow in;
  in.buffer = 0.1, in.velocity = 2.0, in.ramp_time = 2.0, in.y_min = 1.0, in.y_max = 3.0;
  CHECK(in.profile(2.0, 10.0) == Approx(3.0).epsilon(1e-14)); // centre line 1.5 U0
  CHECK(in.profile(2.0, 1.0) == Approx(1.5).epsilon(1e-14));  // half way up the ramp
  CHECK(in.profile(1.0, 10.0) == 0.0);
  CHECK(in.profile(3.5, 10.0) == 0.0);
  // Mean over the height = U0 (midpoint rule, 1000 strips).
  double mean = 0.0;
  for (int k = 0; k < 1000; ++k) mean += in.profile(1.0 + 2.0 * (k + 0.5) / 1000.0, 10.0) / 1000.0;
  CHECK(mean == Approx(2.0).epsilon(1e-5));

  sph::SphOptions o = channel_options(1.0, 4.0, 0.05);
  o.periodic_x = false;
  CHECK_THROWS_WITH(o.validate(), Catch::Contains("needs periodic_x"));
  o = channel_options(1.0, 4.0, 0.05);
  o.inflow.buffer = 2.5;
  CHECK_THROWS_WITH(o.validate(), Catch::Contains("inflow.buffer"));
}

TEST_CASE("sph: channel with an inflow buffer develops plane Poiseuille flow", "[sph][inflow]") {
  const double H = 1.0, L = 5.0, dp = H / 20.0, U0 = 1.0;
  const sph::SphOptions o = channel_options(H, L, dp);
  set_sequential(true);
  sph::SphFluid f(o, sph::fill_rectangle({0.0, 0.0}, {L, H}, dp), channel_walls(H, L));
  f.advance_to(5.0); // the slowest start-up mode decays as exp(-pi^2 nu t / H^2)
  // Averages over 5 <= t <= 6 of the section 2.5 <= x < 4.5 (0.5 H to 3.5 H behind the buffer):
  // u in 20 bins of y, the mass flux per unit depth, the pressure gradient (least squares).
  const int bins = 20, samples = 50;
  const double xa = 2.5, xb = 4.5;
  std::vector<double> su(bins, 0.0), sy(bins, 0.0), n(bins, 0.0);
  double flux = 0.0, slope = 0.0;
  const std::size_t before = f.particles().size();
  for (int s = 1; s <= samples; ++s) {
    f.advance_to(5.0 + s / static_cast<double>(samples));
    const auto& p = f.particles();
    double m = 0, sx = 0, sp = 0, sxx = 0, sxp = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (p.x[0][i] < xa || p.x[0][i] >= xb) continue;
      const int b = std::clamp(static_cast<int>(p.x[1][i] / H * bins), 0, bins - 1);
      su[b] += p.v[0][i], sy[b] += p.x[1][i], n[b] += 1.0;
      flux += o.mass() * p.v[0][i] / (xb - xa) / samples;
      const double pr = f.pressure(i);
      m += 1, sx += p.x[0][i], sp += pr, sxx += p.x[0][i] * p.x[0][i], sxp += p.x[0][i] * pr;
    }
    slope += (m * sxp - sx * sp) / (m * sxx - sx * sx) / samples;
  }
  set_sequential(false);
  const double u_max = 1.5 * U0, mu = o.rho0 * o.viscosity;
  double worst = 0.0;
  for (int b = 0; b < bins; ++b) {
    const double y = sy[b] / n[b], exact = 6.0 * U0 * y * (H - y) / (H * H);
    worst = std::max(worst, std::abs(su[b] / n[b] - exact) / u_max);
  }
  const double flux_exact = o.rho0 * U0 * H, slope_exact = -12.0 * mu * U0 / (H * H);
  INFO("max |u - u_exact| / u_max " << worst << "; flux " << flux << " vs " << flux_exact
                                    << "; dp/dx " << slope << " vs " << slope_exact);
  CHECK(f.particles().size() == before);
  CHECK(f.removed() == 0);
  CHECK(worst < 0.02);
  CHECK(std::abs(flux / flux_exact - 1.0) < 0.02);
  CHECK(std::abs(slope / slope_exact - 1.0) < 0.1);
}

TEST_CASE("sph: the inflow channel: two threads bitwise the sequential run, restart bitwise",
          "[sph][inflow][threads][restart]") {
  const double H = 1.0, L = 2.5, dp = H / 20.0;
  const sph::SphOptions o = channel_options(H, L, dp);
  const auto x = sph::fill_rectangle({0.0, 0.0}, {L, H}, dp);
  set_sequential(true);
  sph::SphFluid a(o, x, channel_walls(H, L));
  for (int s = 0; s < 150; ++s) a.advance(a.next_dt());
  StateArchive archive;
  a.write_state(archive, "fluid/"); // mid advection step (150 acoustic steps)
  for (int s = 0; s < 100; ++s) a.advance(a.next_dt());
  set_sequential(false);
  sph::SphFluid b(o, x, channel_walls(H, L));
  for (int s = 0; s < 250; ++s) b.advance(b.next_dt());
  CHECK(num_threads() >= 1);
  CHECK(sph::same_state(a, b));
  sph::SphFluid c(o, x, channel_walls(H, L));
  c.read_state(archive, "fluid/");
  for (int s = 0; s < 100; ++s) c.advance(c.next_dt());
  CHECK(sph::same_state(a, c));
  INFO("t " << a.time() << " s, kinetic energy " << a.kinetic_energy() << " J/m");
  CHECK(a.kinetic_energy() > 0.1); // the buffer has set the flow going (developed: 1.5 J/m)
}
