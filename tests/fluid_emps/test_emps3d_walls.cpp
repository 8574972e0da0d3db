// The EMPS fluid in 3-D with ERP walls of triangles (#43): pnd = n0 for a lattice at rest filling
// a box (faces, concave edges with two walls, corners with three), and the hydrostatic tank
// (a report: its pressure and energy criteria are not yet met).
#include "fluid_emps/emps_fluid.hpp"
#include "geometry_erp/box_walls.hpp"
#include "test_support.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace fsi;

namespace {

/// The lattice at l0/2 + k l0 filling [0, nx l0] x [0, ny l0] x [0, nz l0].
std::vector<Vec3> block(int nx, int ny, int nz, double l0) {
  std::vector<Vec3> x;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) x.push_back(l0 * Vec3(i + 0.5, j + 0.5, k + 0.5));
  return x;
}

/// How many of the box [0, L]^3's walls lie within r_e of x.
int walls_near(const Vec3& x, double L, double r_e) {
  int n = 0;
  for (int a = 0; a < 3; ++a) n += (x[a] < r_e) + (L - x[a] < r_e);
  return n;
}

} // namespace

TEST_CASE("emps 3-D walls: a lattice at rest filling a box has pnd = n0 at faces, edges and "
          "corners",
          "[emps][walls3d]") {
  const double l0 = 0.01;
  const int n = 10; // some particles 4 l0 from all but one wall
  const double L = n * l0;
  erp::TriangleWallSet walls;
  erp::add_box_tank(walls, Vec3::Zero(), Vec3::Constant(L), false, 0);
  for (const double re : {3.1, 2.1, 4.0}) {
    emps::FluidOptions3 options = emps::test::water<3>(l0, -0.05, 0.15);
    options.re_over_l0 = re;
    const double r_e = re * l0;
    emps::EmpsFluid3 fluid(options, block(n, n, n, l0), walls);
    const auto& p = fluid.particles();
    std::array<double, 4> worst{}; // by the number of walls within r_e
    std::array<int, 4> count{};
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Vec3 x(p.position[0][i], p.position[1][i], p.position[2][i]);
      const int k = std::min(walls_near(x, L, r_e), 3);
      ++count[static_cast<std::size_t>(k)];
      worst[static_cast<std::size_t>(k)] = std::max(worst[static_cast<std::size_t>(k)],
                                                    std::abs(p.pnd[i] - fluid.n0()) / fluid.n0());
    }
    INFO("r_e/l0 = " << re << ": worst |pnd - n0|/n0 with 1, 2, 3 walls near: " << worst[1] << ", "
                     << worst[2] << ", " << worst[3]);
    CHECK(count[1] > 0);
    CHECK(count[2] > 0);
    CHECK(count[3] > 0);
    for (const double e : worst) CHECK(e < 1e-12);
  }
  SECTION("without the corner faces the edges and corners count their wall lattice once per wall "
          "they miss") {
    emps::FluidOptions3 options = emps::test::water<3>(l0, -0.05, 0.15);
    options.wall.corner_faces = false;
    emps::EmpsFluid3 fluid(options, block(n, n, n, l0), walls);
    const double corner = fluid.particles().pnd[0]; // at (l0/2, l0/2, l0/2)
    CHECK(corner < 0.9 * fluid.n0());
  }
}

namespace {

/// The 3-D hydrostatic tank's figures (docs/fluid_emps.md, "3-D").
struct TankRun {
  double p_bottom = 0;     ///< mean bottom-layer pressure over the last second
  double p_bulk = 0;       ///< the same over its particles r_e or more from the side walls
  double p_exact = 0;      ///< rho g (H - l0/2)
  double ke_damped = 0;    ///< kinetic energy at the end of the damping phase
  double ke_after_max = 0; ///< its largest value after that
  double ke_end = 0;       ///< at the end
  double mean_speed = 0;   ///< at the end, over sqrt(g H)
  double min_gap = 1e300;  ///< smallest distance of a particle centre to the box's walls
  std::size_t removed = 0;
  long steps = 0;
};

/// Still water of depth H = nz l0 filling the floor nx l0 x ny l0 of a tank of triangles 2 H high,
/// the shipped 2-D tank's recipe (wall_model default, alpha_rep 1e5, damped for T_d).
TankRun hydrostatic_tank(const erp::TriangleWallSet& walls, int nx, int ny, int nz, double l0,
                         double t_damp, double t_end) {
  emps::FluidOptions3 o = emps::test::water<3>(l0, -0.1, 1.0);
  emps::apply_wall_preset(o, emps::WallModel::standard);
  o.viscosity = 1e-6;
  o.sound_speed = 15.0;
  o.wall.contact.alpha_rep = 1e5;
  o.damping_time = t_damp;
  o.gravity = Vec3(0, 0, -9.81);
  emps::EmpsFluid3 fluid(o, block(nx, ny, nz, l0), walls);
  const double H = nz * l0, dt = 5e-4, g = 9.81; // c dt / l0 = 0.375
  const Vec3 hi(nx * l0, ny * l0, 2 * H);
  TankRun out;
  out.p_exact = o.density * g * (H - 0.5 * l0);
  const auto& p = fluid.particles();
  double p_sum = 0.0, p_bulk_sum = 0.0;
  long p_samples = 0;
  const long steps = std::lround(t_end / dt), damped = std::lround(t_damp / dt),
             last_half = std::lround((t_end - 0.5) / dt);
  for (long s = 0; s < steps; ++s) {
    fluid.advance(s * dt, dt);
    const double ke = fluid.kinetic_energy();
    if (s + 1 == damped) out.ke_damped = ke;
    if (s + 1 > damped) out.ke_after_max = std::max(out.ke_after_max, ke);
    for (std::size_t i = 0; i < p.size(); ++i)
      for (int a = 0; a < 3; ++a)
        out.min_gap = std::min({out.min_gap, p.position[a][i], hi[a] - p.position[a][i]});
    if (s + 1 <= last_half) continue;
    double sum = 0.0, bulk = 0.0;
    int bottom = 0, in_bulk = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (p.position[2][i] >= l0) continue;
      sum += p.p[i], ++bottom;
      bool away = true;
      for (int a = 0; a < 2; ++a)
        away = away && std::min(p.position[a][i], hi[a] - p.position[a][i]) >= o.r_e();
      if (away) bulk += p.p[i], ++in_bulk;
    }
    p_sum += sum / bottom;
    p_bulk_sum += bulk / in_bulk;
    ++p_samples;
  }
  out.p_bottom = p_sum / static_cast<double>(p_samples);
  out.p_bulk = p_bulk_sum / static_cast<double>(p_samples);
  out.ke_end = fluid.kinetic_energy();
  double v2 = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (int a = 0; a < 3; ++a) v2 += p.velocity[a][i] * p.velocity[a][i];
  out.mean_speed = std::sqrt(v2 / static_cast<double>(p.size())) / std::sqrt(g * H);
  out.removed = fluid.removed();
  out.steps = fluid.steps();
  return out;
}

/// Reports the acceptance figures of #43 and asserts what the run meets today: no particle left
/// the tank or crossed a wall. The bottom pressure (1 % of rho g (H - l0/2) asked) and the falling
/// kinetic energy are not yet met (docs/fluid_emps.md, "3-D").
void report_tank(const TankRun& r, double l0) {
  WARN("bottom pressure " << r.p_bottom << " Pa against rho g (H - l0/2) = " << r.p_exact
                          << " Pa: " << 100.0 * (r.p_bottom / r.p_exact - 1.0)
                          << " % (away from the side walls " << 100.0 * (r.p_bulk / r.p_exact - 1.0)
                          << " %); kinetic energy after the damping " << r.ke_damped
                          << " J, largest after " << r.ke_after_max << " J, at the end " << r.ke_end
                          << " J; rms speed " << r.mean_speed
                          << " sqrt(gH); nearest centre to a wall " << r.min_gap / l0 << " l0");
  CHECK(r.removed == 0);
  CHECK(r.min_gap > 0.0); // no particle through a wall (the run's guard also stops on one)
}

} // namespace

// The acceptance run of #43, its pressure and energy criteria not yet met (docs/fluid_emps.md,
// "3-D": the bulk reads -0.26 %, the whole bottom layer +9.6 %).
TEST_CASE("emps 3-D walls: report: still water in a box tank of triangles", "[walls3d][slow]") {
  const double l0 = 0.02;
  erp::TriangleWallSet walls;
  erp::add_box_tank(walls, Vec3::Zero(), Vec3(10 * l0, 10 * l0, 20 * l0), false, 0);
  const TankRun r = hydrostatic_tank(walls, 10, 10, 10, l0, 1.0, 2.0);
  report_tank(r, l0);
}
