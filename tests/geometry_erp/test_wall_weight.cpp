// Wall weight z(r) (eq. 20), n0 (eq. 9) and lambda0 (eq. 12) on the lattice that continues the
// fluid lattice behind a flat wall.
#include "geometry_erp/wall_weight.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <utility>

using namespace fsi::erp;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using fsi::particles::MpsWeight;

namespace {

/// n_i of the fluid particle in column 0, row k of a block of fluid rows 0..rows-1 at
/// y = l0/2 + k l0 and columns -half..half (sum over the real particles only, eq. 9).
double block_pnd(int k, int rows, int half, double l0, const WeightFunction& w) {
  double n = 0.0;
  for (int row = 0; row < rows; ++row)
    for (int i = -half; i <= half; ++i)
      if (row != k || i != 0) n += w(std::hypot(i * l0, (row - k) * l0));
  return n;
}

} // namespace

TEST_CASE("erp: n0 and lambda0 of the quadratic weight for r_e = 1.5 l0, square and cubic "
          "lattices",
          "[wall_weight]") {
  // Neighbours within r_e: 4 at l0 and 4 at sqrt(2) l0 in 2-D; 6 at l0 and 12 at sqrt(2) l0 in 3-D
  // (the 8 at sqrt(3) l0 lie beyond r_e).
  const double l0 = 0.01, r_e = 1.5 * l0;
  const MpsWeight w(r_e);
  const double w1 = std::pow(1.0 / 1.5 - 1.0, 2), w2 = std::pow(std::sqrt(2.0) / 1.5 - 1.0, 2);
  const double n0 = 4.0 * w1 + 4.0 * w2, n0_3 = 6.0 * w1 + 12.0 * w2;
  CHECK_THAT(lattice_n0(l0, r_e, w), WithinRel(n0, 1e-14));
  CHECK_THAT(lattice_lambda0(l0, r_e, w),
             WithinRel((4.0 * w1 * l0 * l0 + 8.0 * w2 * l0 * l0) / n0, 1e-14));
  CHECK_THAT(lattice_n0<3>(l0, r_e, w), WithinRel(n0_3, 1e-14));
  CHECK_THAT(lattice_lambda0<3>(l0, r_e, w),
             WithinRel((6.0 * w1 * l0 * l0 + 24.0 * w2 * l0 * l0) / n0_3, 1e-14));
}

TEST_CASE("erp: z(r) table matches the direct lattice sum", "[wall_weight]") {
  const double l0 = 1.46e-3, r_e = 3.1 * l0;
  const MpsWeight w(r_e);
  const WallWeightTable z(l0, r_e, w);
  const double dr = z.spacing();
  const double n0 = lattice_n0(l0, r_e, w);
  CHECK(z(0.0) > 0.3 * n0);
  double worst_between = 0.0;
  for (int k = 0; k * dr < r_e; ++k) {
    REQUIRE_THAT(z(k * dr), WithinAbs(wall_weight_sum(k * dr, l0, r_e, w), 1e-10));
    const double r = (k + 0.5) * dr;
    worst_between = std::max(worst_between, std::abs(z(r) - wall_weight_sum(r, l0, r_e, w)));
  }
  CHECK(worst_between < 1e-4);
  CHECK(z(r_e) == 0.0);
  CHECK(z(r_e - 0.5 * l0 + 1e-9 * l0) == 0.0);
}

TEST_CASE("erp: n_i + z(r_i) = n0 for every fluid row next to a flat wall", "[wall_weight]") {
  const double l0 = 1.0;
  for (const double r_e : {2.1, 3.1, 4.0}) {
    const MpsWeight quadratic(r_e);
    // The classic MPS weight r_e/r - 1 as a replacement weight.
    const WeightFunction classic = [r_e](double r) { return r < r_e ? r_e / r - 1.0 : 0.0; };
    for (const WeightFunction& w : {WeightFunction(quadratic), classic}) {
      const WallWeightTable z(l0, r_e, w);
      const double n0 = lattice_n0(l0, r_e, w);
      const int rows = 12, half = 10;
      for (int k = 0; k < 6; ++k) {
        const double r_i = 0.5 * l0 + k * l0;
        INFO("r_e = " << r_e << ", row " << k);
        REQUIRE_THAT(block_pnd(k, rows, half, l0, w) + z(r_i), WithinAbs(n0, 1e-12));
      }
    }
  }
}

TEST_CASE("erp: z(a) + z(b) - q(a, b) completes n_i to n0 in a right-angle corner",
          "[wall_weight]") {
  // A quadrant of fluid lattice (x, y > 0) in a corner; every particle within r_e of both walls.
  const double l0 = 1.0;
  for (const double r_e : {2.1, 3.1, 4.0}) {
    const MpsWeight w(r_e);
    const WallWeightTable z(l0, r_e, w);
    const double n0 = lattice_n0(l0, r_e, w);
    const int size = 12;
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) {
        double n = 0.0;
        for (int i = 0; i < size; ++i)
          for (int j = 0; j < size; ++j)
            if (i != a || j != b) n += w(std::hypot((i - a) * l0, (j - b) * l0));
        const double ra = 0.5 * l0 + a * l0, rb = 0.5 * l0 + b * l0;
        INFO("r_e = " << r_e << ", column " << a << ", row " << b);
        REQUIRE_THAT(n + z(ra) + z(rb) - corner_weight_sum(ra, rb, l0, r_e, w),
                     WithinAbs(n0, 1e-12));
      }
  }
}

TEST_CASE("erp: eq. 10's lattice sums of a flat wall and of a convex corner balance the fluid's",
          "[wall_weight]") {
  // On the full lattice sum_j (x_j - x_i) w / r^2 = 0. Next to a flat wall (fluid at y > 0) the
  // fluid part is +wall_gradient_sum along the normal; beside a convex corner (solid x > 0,
  // y < 0) the three fluid quadrants' part is minus the solid quadrant's corner_gradient_sum.
  const double l0 = 1.0;
  for (const double r_e : {2.1, 3.1, 4.0}) {
    const MpsWeight w(r_e);
    const int reach = 6;
    for (int k = 0; k < 4; ++k) { // flat wall, particle in row k, column 0
      double gy = 0.0;
      for (int row = 0; row < k + reach; ++row)
        for (int i = -reach; i <= reach; ++i) {
          const double dy = (row - k) * l0, r2 = i * l0 * i * l0 + dy * dy;
          if (r2 > 0.0) gy += dy / r2 * w(std::sqrt(r2));
        }
      INFO("r_e = " << r_e << ", row " << k);
      REQUIRE_THAT(gy, WithinAbs(wall_gradient_sum(0.5 * l0 + k * l0, l0, r_e, w), 1e-12));
    }
    for (int a = 0; a < 4; ++a) // particle at (-a', b') outside the corner, a' = l0/2 + a l0
      for (int b = 0; b < 4; ++b) {
        const double xa = -(0.5 + a) * l0, yb = (0.5 + b) * l0;
        double gx = 0.0, gy = 0.0;
        for (int i = -reach - a; i <= reach; ++i)
          for (int j = -reach; j <= reach + b; ++j) {
            const double x = (i + 0.5) * l0, y = (j + 0.5) * l0;
            if (x > 0.0 && y < 0.0) continue; // the solid
            const double dx = x - xa, dy = y - yb, r2 = dx * dx + dy * dy;
            if (r2 > 0.0) gx += dx / r2 * w(std::sqrt(r2)), gy += dy / r2 * w(std::sqrt(r2));
          }
        const auto q = corner_gradient_sum(-xa, yb, l0, r_e, w); // towards +x and -y
        INFO("r_e = " << r_e << ", a = " << a << ", b = " << b);
        REQUIRE_THAT(gx + q.x(), WithinAbs(0.0, 1e-12));
        REQUIRE_THAT(gy - q.y(), WithinAbs(0.0, 1e-12));
      }
  }
}

namespace {

/// n0 and sum r^2 w over the cubic lattice of spacing l0 written out: every offset (i, j, k) up to
/// r_e / l0 + 2 per axis, the quadratic weight (1 - r / r_e)^2 inside r_e (eq. 8) spelled here.
std::pair<double, double> cubic_lattice_sums(double l0, double r_e) {
  const int m = static_cast<int>(r_e / l0) + 2;
  double n0 = 0.0, r2w = 0.0;
  for (int i = -m; i <= m; ++i)
    for (int j = -m; j <= m; ++j)
      for (int k = -m; k <= m; ++k) {
        const double r = l0 * std::sqrt(double(i * i + j * j + k * k));
        if ((i == 0 && j == 0 && k == 0) || r >= r_e) continue;
        const double w = (1.0 - r / r_e) * (1.0 - r / r_e);
        n0 += w;
        r2w += r * r * w;
      }
  return {n0, r2w};
}

} // namespace

TEST_CASE("erp: n0 and lambda0 on the 3-D cubic lattice equal the sums written out",
          "[wall_weight]") {
  for (const double ratio : {2.1, 3.1, 4.0}) {
    const double l0 = 1.46e-3, r_e = ratio * l0;
    const auto [n0, r2w] = cubic_lattice_sums(l0, r_e);
    INFO("r_e / l0 = " << ratio);
    CHECK_THAT(lattice_n0<3>(l0, r_e, MpsWeight(r_e)), WithinRel(n0, 1e-12));
    CHECK_THAT(lattice_lambda0<3>(l0, r_e, MpsWeight(r_e)), WithinRel(r2w / n0, 1e-12));
  }
}

TEST_CASE("erp: n0 and lambda0 on the 3-D cubic lattice tend to their continuum values",
          "[wall_weight]") {
  // For l0 << r_e the sums become integrals with 4 pi r^2 dr / l0^3 and w = (1 - r / r_e)^2:
  // n0 -> (4 pi / 30) (r_e / l0)^3 and lambda0 -> (1/105) / (1/30) r_e^2 = (2/7) r_e^2 (the 2-D
  // lattice would give 2 pi / 12 (r_e / l0)^2 and r_e^2 / 5). Measured deviation at r_e = 20 l0:
  // 3e-4 for both.
  const double l0 = 1e-3, r_e = 20.0 * l0;
  const MpsWeight w(r_e);
  CHECK_THAT(lattice_n0<3>(l0, r_e, w), WithinRel(4.0 * std::numbers::pi / 30.0 * 8000.0, 1e-3));
  CHECK_THAT(lattice_lambda0<3>(l0, r_e, w), WithinRel(2.0 / 7.0 * r_e * r_e, 1e-3));
}

TEST_CASE("erp: the 2-D z(r), its gradient sum and table are bitwise those before the D template",
          "[wall_weight]") {
  // {r_e / l0, r / l0, wall_weight_sum, wall_gradient_sum, table z, table dz/dr} printed as hex
  // floats by commit 98c2c94 (before wall_weight became a template on D), l0 = 1.46e-3.
  constexpr double before[][6] = {
      {0x1.0cccccccccccdp+1, 0x0p+0, 0x1.23e2447849d14p+0, 0x1.e28105690e74bp+9,
       0x1.23e2447849d14p+0, 0x0p+0},
      {0x1.0cccccccccccdp+1, 0x1.0a3d70a3d70a4p-3, 0x1.e06e02576d73fp-1, 0x1.525e03ae1be33p+9,
       0x1.e06e025782385p-1, -0x1.f74f5ae7a905cp+9},
      {0x1.0cccccccccccdp+1, 0x1p-1, 0x1.f5b11697e00aep-2, 0x1.05bffac9f4875p+8,
       0x1.f5b11697e00aep-2, -0x1.51019a0122815p+9},
      {0x1.0cccccccccccdp+1, 0x1.5eb851eb851ecp+0, 0x1.8911409f029f4p-7, 0x1.1931175c814acp+2,
       0x1.8911409f01f67p-7, -0x1.1dc6c2de96357p+6},
      {0x1.0cccccccccccdp+1, 0x1.0666666666666p+1, 0x0p+0, 0x0p+0, 0x0p+0, 0x0p+0},
      {0x1.8cccccccccccdp+1, 0x0p+0, 0x1.413b98bc4fe6dp+1, 0x1.6f32497164907p+10,
       0x1.413b98bc4fe6dp+1, 0x0p+0},
      {0x1.8cccccccccccdp+1, 0x1.0a3d70a3d70a4p-3, 0x1.1cca6f614b3ccp+1, 0x1.1fad0b6172d42p+10,
       0x1.1cca6f614b42dp+1, -0x1.6ea6a268c74f4p+10},
      {0x1.8cccccccccccdp+1, 0x1p-1, 0x1.80d8a7b0ffb6dp+0, 0x1.39576ea9d8405p+9,
       0x1.80d8a7b0ffb6dp+0, -0x1.2adb7dd7bc577p+10},
      {0x1.8cccccccccccdp+1, 0x1.5eb851eb851ecp+0, 0x1.8ffa49084126bp-2, 0x1.e2a24500b6588p+6,
       0x1.8ffa4908413c2p-2, -0x1.0e96e1d5b0f06p+9},
      {0x1.8cccccccccccdp+1, 0x1.0666666666666p+1, 0x1.dff66f57cbe31p-5, 0x1.d886d06eb2486p+3,
       0x1.dff66f57cc2bdp-5, -0x1.5c641b2e17c21p+7},
  };
  for (const auto& [ratio, f, z_sum, g_sum, z_table, dz_table] : before) {
    const double l0 = 1.46e-3, r_e = ratio * l0, r = f * l0;
    const MpsWeight w(r_e);
    const WallWeightTable z(l0, r_e, w);
    INFO("r_e / l0 = " << ratio << ", r / l0 = " << f);
    CHECK(wall_weight_sum(r, l0, r_e, w) == z_sum);
    CHECK(wall_gradient_sum(r, l0, r_e, w) == g_sum);
    CHECK(z(r) == z_table);
    CHECK(z.dz_dr(r) == dz_table);
  }
}
