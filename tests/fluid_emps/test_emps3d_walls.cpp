// The EMPS fluid in 3-D with ERP walls of triangles (#43): pnd = n0 for a lattice at rest filling
// a box (faces, concave edges with two walls, corners with three), and the hydrostatic tank's
// acceptance, its walls made by keys and read from an STL file.
#include "fluid_emps/emps_fluid.hpp"
#include "geometry_erp/box_walls.hpp"
#include "geometry_erp/stl_reader.hpp"
#include "test_support.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>

using namespace fsi;

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
    emps::EmpsFluid3 fluid(options, emps::test::block(n, n, n, l0), walls);
    const auto& p = fluid.particles();
    std::array<double, 4> worst{}; // by the number of walls within r_e
    std::array<int, 4> count{};
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Vec3 x(p.position[0][i], p.position[1][i], p.position[2][i]);
      const int k = std::min(emps::test::walls_near(x, L, r_e), 3);
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
    emps::EmpsFluid3 fluid(options, emps::test::block(n, n, n, l0), walls);
    const double corner = fluid.particles().pnd[0]; // at (l0/2, l0/2, l0/2)
    CHECK(corner < 0.9 * fluid.n0());
  }
}

namespace {

/// The 3-D hydrostatic tank's figures (docs/fluid_emps.md, "3-D").
struct TankRun {
  /// Mean bottom-layer pressure over the last 0.5 s: all of the layer, and split by the side
  /// walls within r_e of a particle: none (the floor's interior), one (an edge), two (a corner).
  double p_bottom = 0;
  std::array<double, 3> p_by_walls{};
  double p_exact = 0;      ///< rho g (H - l0/2)
  double ke_damped = 0;    ///< kinetic energy at the end of the damping phase
  double ke_after_max = 0; ///< its largest value after that
  double ke_end = 0;       ///< at the end
  double min_gap = 1e300;  ///< smallest distance of a particle centre to the box's walls
  std::size_t removed = 0;
};

/// Still water of depth H = nz l0 filling the floor nx l0 x ny l0 of a tank of triangles 2 H high,
/// the shipped 2-D tank's recipe (wall_model default, alpha_rep 1e5, damped for T_d = 2 s).
TankRun hydrostatic_tank(const erp::TriangleWallSet& walls, int nx, int ny, int nz, double l0,
                         double t_damp, double t_end) {
  emps::FluidOptions3 o = emps::test::water<3>(l0, -0.1, 1.0);
  emps::apply_wall_preset(o, emps::WallModel::standard);
  o.viscosity = 1e-6;
  o.sound_speed = 15.0;
  o.wall.contact.alpha_rep = 1e5;
  o.damping_time = t_damp;
  o.gravity = Vec3(0, 0, -9.81);
  emps::EmpsFluid3 fluid(o, emps::test::block(nx, ny, nz, l0), walls);
  const double H = nz * l0, dt = 5e-4, g = 9.81; // c dt / l0 = 0.375
  const Vec3 hi(nx * l0, ny * l0, 2 * H);
  TankRun out;
  out.p_exact = o.density * g * (H - 0.5 * l0);
  const auto& p = fluid.particles();
  double p_sum = 0.0;
  std::array<double, 3> by_walls{};
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
    double sum = 0.0;
    int bottom = 0;
    std::array<double, 3> sum_by{};
    std::array<int, 3> count_by{};
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (p.position[2][i] >= l0) continue;
      sum += p.p[i], ++bottom;
      std::size_t near = 0;
      for (int a = 0; a < 2; ++a)
        near += std::min(p.position[a][i], hi[a] - p.position[a][i]) < o.r_e();
      sum_by[near] += p.p[i], ++count_by[near];
    }
    p_sum += sum / bottom;
    for (std::size_t k = 0; k < 3; ++k) by_walls[k] += sum_by[k] / count_by[k];
    ++p_samples;
  }
  const auto samples = static_cast<double>(p_samples);
  out.p_bottom = p_sum / samples;
  for (std::size_t k = 0; k < 3; ++k) out.p_by_walls[k] = by_walls[k] / samples;
  out.ke_end = fluid.kinetic_energy();
  out.removed = fluid.removed();
  return out;
}

/// Reports the acceptance figures of #43 for the tank and asserts what the run meets today: no
/// particle left the tank or crossed a wall, the kinetic energy after the damping phase never
/// above its value at its end. The bottom layer within 1 % of rho g (H - l0/2) is not yet met
/// (docs/fluid_emps.md, "3-D").
void report_tank(const TankRun& r, double l0) {
  const auto percent = [&](double p) { return 100.0 * (p / r.p_exact - 1.0); };
  WARN("bottom layer " << percent(r.p_bottom) << " % of rho g (H - l0/2) = " << r.p_exact
                       << " Pa; with 0, 1, 2 side walls near " << percent(r.p_by_walls[0]) << " %, "
                       << percent(r.p_by_walls[1]) << " %, " << percent(r.p_by_walls[2])
                       << " %; kinetic energy after the damping " << r.ke_damped
                       << " J, largest after " << r.ke_after_max << " J, at the end " << r.ke_end
                       << " J; nearest centre to a wall " << r.min_gap / l0 << " l0");
  CHECK(r.removed == 0);
  CHECK(r.min_gap > 0.0); // no particle through a wall (the run's guard also stops on one)
  CHECK(r.ke_after_max <= r.ke_damped);
  CHECK(r.ke_end < r.ke_damped);
}

/// The walls as an ASCII STL file at `path`, each facet's normal the fluid normal.
void write_stl(const erp::TriangleWallSet& walls, const std::filesystem::path& path) {
  std::ofstream out(path);
  out << std::setprecision(17) << "solid tank\n";
  const std::vector<Vec3>& x = walls.nodes().x;
  for (std::size_t t = 0; t < walls.triangles().size(); ++t) {
    const Vec3& n = walls.face_normal(static_cast<int>(t));
    out << "facet normal " << n[0] << ' ' << n[1] << ' ' << n[2] << "\n outer loop\n";
    for (const int v : walls.triangles().node[t]) {
      const Vec3& xv = x[static_cast<std::size_t>(v)];
      out << "  vertex " << xv[0] << ' ' << xv[1] << ' ' << xv[2] << "\n";
    }
    out << " endloop\nendfacet\n";
  }
  out << "endsolid tank\n";
}

} // namespace

// The acceptance run of #43, its bottom-pressure criterion not yet met (docs/fluid_emps.md, "3-D").
TEST_CASE("emps 3-D walls: report: still water in a box tank of triangles", "[walls3d][slow]") {
  const double l0 = 0.02;
  erp::TriangleWallSet walls;
  erp::add_box_tank(walls, Vec3::Zero(), Vec3(10 * l0, 10 * l0, 20 * l0), false, 0);
  report_tank(hydrostatic_tank(walls, 10, 10, 10, l0, 2.0, 3.0), l0);
}

TEST_CASE("emps 3-D walls: report: still water in a box tank read from an STL file",
          "[walls3d][slow]") {
  const double l0 = 0.02;
  erp::TriangleWallSet box;
  erp::add_box_tank(box, Vec3::Zero(), Vec3(10 * l0, 10 * l0, 20 * l0), false, 0);
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / "test_emps3d_walls_tank.stl";
  write_stl(box, file);
  const erp::StlSurface stl = erp::read_stl_file(file.string());
  std::filesystem::remove(file);
  CHECK(stl.open_edges == 0);
  erp::TriangleWallSet walls;
  walls.add_triangles(stl.points, stl.triangles, 0);
  report_tank(hydrostatic_tank(walls, 10, 10, 10, l0, 2.0, 3.0), l0);
}
