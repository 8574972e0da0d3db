// The EMPS fluid in 3-D with ERP walls of triangles (#43): pnd = n0 for a lattice at rest filling
// a box (faces, concave edges with two walls, corners with three).
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
