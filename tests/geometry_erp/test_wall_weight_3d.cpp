// Wall weight z(r) (eq. 20) and eq. 10's wall gradient sum on the cubic lattice (D = 3): a flat
// wall at z = 0, fluid layers at l0/2 + k l0, virtual layers at -l0/2 - m l0.
#include "geometry_erp/wall_weight.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace fsi::erp;
using Catch::Matchers::WithinAbs;
using fsi::particles::MpsWeight;

namespace {

/// Sums over the real particles of a block of fluid layers 0..layers-1 and columns
/// (i, j) in [-half, half]^2, for the particle in column (0, 0), layer k: n_i (eq. 9) and the
/// normal component of sum (x_j - x_i) w / r^2 (eq. 10).
struct BlockSums {
  double n = 0.0, g = 0.0;
};

BlockSums block_sums(int k, int layers, int half, double l0, const WeightFunction& w) {
  BlockSums s;
  for (int layer = 0; layer < layers; ++layer)
    for (int j = -half; j <= half; ++j)
      for (int i = -half; i <= half; ++i) {
        if (layer == k && i == 0 && j == 0) continue;
        const double dz = (layer - k) * l0;
        const double r2 = (i * i + j * j) * l0 * l0 + dz * dz;
        s.n += w(std::sqrt(r2));
        s.g += dz / r2 * w(std::sqrt(r2));
      }
  return s;
}

} // namespace

TEST_CASE("erp: n_i + z(r_i) = n0 on every fluid layer next to a flat wall, cubic lattice",
          "[wall_weight][3d]") {
  const double l0 = 1.0;
  for (const double r_e : {2.1, 3.1, 4.0}) {
    const MpsWeight quadratic(r_e);
    const WeightFunction classic = [r_e](double r) { return r < r_e ? r_e / r - 1.0 : 0.0; };
    for (const WeightFunction& w : {WeightFunction(quadratic), classic}) {
      const WallWeightTable3 z(l0, r_e, w);
      const double n0 = lattice_n0<3>(l0, r_e, w);
      for (int k = 0; k < 6; ++k) {
        const double r_i = 0.5 * l0 + k * l0;
        const double n_i = block_sums(k, 12, 6, l0, w).n;
        INFO("r_e = " << r_e << ", layer " << k);
        REQUIRE_THAT(n_i + wall_weight_sum<3>(r_i, l0, r_e, w), WithinAbs(n0, 1e-12));
        REQUIRE_THAT(n_i + z(r_i), WithinAbs(n0, 1e-12));
      }
    }
  }
}

TEST_CASE("erp: the 3-D z(r) vanishes from r_e - l0/2 on and exceeds the 2-D one",
          "[wall_weight][3d]") {
  const double l0 = 1.46e-3, r_e = 3.1 * l0;
  const MpsWeight w(r_e);
  const WallWeightTable3 z(l0, r_e, w);
  CHECK(wall_weight_sum<3>(r_e - 0.5 * l0, l0, r_e, w) == 0.0);
  CHECK(z(r_e - 0.5 * l0) == 0.0);
  CHECK(z(r_e) == 0.0);
  CHECK(z.dz_dr(r_e) == 0.0);
  CHECK(wall_weight_sum<3>(r_e - 0.51 * l0, l0, r_e, w) > 0.0);
  // A virtual layer holds more particles than a virtual row: z3 > z2 where a virtual point off
  // the particle's column (i, j) = (0, 0) lies within r_e (up to r = 1.5 l0 here; at 2.5 l0 only
  // the point right below counts, and z3 = z2).
  for (const double f : {0.0, 0.5, 1.5})
    CHECK(wall_weight_sum<3>(f * l0, l0, r_e, w) > wall_weight_sum<2>(f * l0, l0, r_e, w));
  double worst = 0.0; // the spline between knots, against the direct sum
  for (int k = 0; (k + 0.5) * z.spacing() < r_e; ++k) {
    const double r = (k + 0.5) * z.spacing();
    worst = std::max(worst, std::abs(z(r) - wall_weight_sum<3>(r, l0, r_e, w)));
  }
  CHECK(worst < 1e-4 * lattice_n0<3>(l0, r_e, w));
}

TEST_CASE("erp: eq. 10's 3-D wall gradient sum balances the fluid half-lattice's",
          "[wall_weight][3d]") {
  // On the full lattice sum_j (x_j - x_i) w / r^2 = 0, so the fluid part along the normal equals
  // the virtual part, wall_gradient_sum<3>.
  const double l0 = 1.0;
  for (const double r_e : {2.1, 3.1, 4.0}) {
    const MpsWeight w(r_e);
    for (int k = 0; k < 5; ++k) {
      INFO("r_e = " << r_e << ", layer " << k);
      REQUIRE_THAT(block_sums(k, k + 6, 6, l0, w).g,
                   WithinAbs(wall_gradient_sum<3>(0.5 * l0 + k * l0, l0, r_e, w), 1e-12));
    }
  }
}
