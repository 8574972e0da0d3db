// The EMPS fluid in 3-D (BasicEmpsFluid<3>, here without walls): n0 and lambda0 of the cubic
// lattice, pnd = n0 inside a block at rest, momentum kept by the pairwise antisymmetric fluid-fluid
// terms (eqs. 10, 11 and the closing-pair viscosity), the pressure gradient pushing a compressed
// blob apart, and a checkpoint that continues bitwise.
#include "fluid_emps/emps_fluid.hpp"
#include "fsi/core/state_archive.hpp"
#include "particles/kernels.hpp"
#include "test_support.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace fsi;
using Catch::Matchers::WithinRel;

namespace {

const erp::TriangleWallSet no_walls; // an empty set: the fluid without walls

emps::FluidOptions3 water3(double l0) {
  return emps::test::water<3>(l0, 0.2, 0.8);
}

/// An n x n x n cube of particles at spacing s, centred at c.
std::vector<Vec3> cube(int n, double s, const Vec3& c) {
  std::vector<Vec3> x;
  const double h = 0.5 * (n - 1);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) x.push_back(c + s * Vec3(i - h, j - h, k - h));
  return x;
}

} // namespace

TEST_CASE("emps 3-D: n0 and lambda0 are the cubic lattice's, and pnd = n0 inside a block at rest",
          "[emps]") {
  const double l0 = 0.01, r_e = 3.1 * l0;
  // The direct sums over the cubic lattice (eqs. 9, 12), the origin left out.
  double n0 = 0.0, r2w = 0.0;
  for (int i = -4; i <= 4; ++i)
    for (int j = -4; j <= 4; ++j)
      for (int k = -4; k <= 4; ++k) {
        const double r = l0 * std::sqrt(double(i * i + j * j + k * k));
        if (r == 0.0 || r >= r_e) continue;
        const double w = (1.0 - r / r_e) * (1.0 - r / r_e);
        n0 += w, r2w += r * r * w;
      }
  emps::EmpsFluid3 fluid(water3(l0), cube(10, l0, {0.5, 0.5, 0.5}), no_walls);
  CHECK_THAT(fluid.n0(), WithinRel(n0, 1e-13));
  CHECK_THAT(fluid.lambda0(), WithinRel(r2w / n0, 1e-13));
  CHECK_THAT(fluid.n0(), WithinRel(11.6594, 1e-4)); // measured; the square lattice: 4.1783
  const auto& p = fluid.particles();
  int inside = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    bool interior = true; // a full support: at least r_e from the block's faces
    for (int a = 0; a < 3; ++a)
      interior = interior && std::abs(p.position[a][i] - 0.5) < 4.5 * l0 - r_e + 1e-9;
    if (!interior) continue;
    ++inside;
    CHECK_THAT(p.pnd[i], WithinRel(fluid.n0(), 1e-13));
    CHECK(p.p[i] == 0.0); // |pnd - n0| only round-off: p of order c^2 rho 1e-13
  }
  CHECK(inside == 8); // 2 x 2 x 2 particles have a full support in a 10-cube at r_e = 3.1 l0
}

TEST_CASE("emps 3-D: without gravity and walls, linear momentum is conserved to 1e-12 per step",
          "[emps]") {
  // The fluid-fluid gradient (eq. 10), the viscous term (eq. 11) and the closing-pair viscosity
  // are antisymmetric in pairs; a blob started squeezed in x and stretched less in y and z (div v
  // = -1/s) keeps its total momentum while pressures rise.
  const double l0 = 0.01;
  auto options = water3(l0);
  options.viscosity = 1e-3;
  options.artificial_viscosity = 0.2;
  emps::EmpsFluid3 fluid(options, cube(12, l0, {0.5, 0.5, 0.5}), no_walls);
  const auto& p0 = fluid.particles();
  std::vector<Vec3> v(p0.size());
  for (std::size_t i = 0; i < p0.size(); ++i)
    v[i] = Vec3(1.0 - 4.0 * (p0.position[0][i] - 0.5), -0.5 + 2.0 * (p0.position[1][i] - 0.5),
                0.25 + 1.0 * (p0.position[2][i] - 0.5));
  const emps::test::MomentumDrift drift = emps::test::momentum_drift(fluid, v, 40, 1e-4);
  CHECK(drift.pressurised > 10000); // the test exercised the pressure gradient
  CHECK(drift.worst < 1e-12);       // round-off (Catch prints the measured value as 0.0)
}

TEST_CASE("emps 3-D: the pressure gradient pushes a compressed blob apart, from high to low "
          "pressure (eq. 10)",
          "[emps]") {
  // A cube at 0.97 l0 spacing: pressure inside, none on its surface (eq. 17), so one step
  // accelerates every particle with an outward pressure drop away from the centre.
  const double l0 = 0.01;
  const Vec3 c(0.5, 0.5, 0.5);
  emps::EmpsFluid3 fluid(water3(l0), cube(10, 0.97 * l0, c), no_walls);
  fluid.advance(0.0, 1e-5);
  const auto& p = fluid.particles();
  int outward = 0, counted = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3 x(p.position[0][i], p.position[1][i], p.position[2][i]);
    const Vec3 u(p.velocity[0][i], p.velocity[1][i], p.velocity[2][i]);
    if ((x - c).norm() < 2.0 * l0) continue; // the centre: the pressure is flat there
    ++counted;
    outward += u.dot(x - c) > 0.0;
  }
  INFO(outward << " of " << counted << " particles move outward");
  CHECK(outward == counted);
}

TEST_CASE("emps 3-D: a run continued from a checkpoint is bitwise the uninterrupted run",
          "[emps]") {
  const double l0 = 0.01;
  auto options = water3(l0);
  options.gravity = {0.0, 0.0, -9.81};
  options.viscosity = 1e-3;
  const auto positions = cube(8, 0.98 * l0, {0.5, 0.5, 0.5});
  emps::EmpsFluid3 a(options, positions, no_walls), b(options, positions, no_walls);
  for (int k = 0; k < 5; ++k) a.advance(k * 1e-4, 1e-4);
  StateArchive archive;
  a.write_state(archive, "fluid/");
  b.read_state(archive, "fluid/");
  for (int k = 5; k < 10; ++k) a.advance(k * 1e-4, 1e-4), b.advance(k * 1e-4, 1e-4);
  REQUIRE(a.particles().size() == b.particles().size());
  for (int axis = 0; axis < 3; ++axis) {
    CHECK(a.particles().position[axis] == b.particles().position[axis]);
    CHECK(a.particles().velocity[axis] == b.particles().velocity[axis]);
  }
  CHECK(a.particles().p == b.particles().p);
}
