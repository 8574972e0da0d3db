// The D-dimensional neighbour list: its rows are the brute-force neighbour sets of a random cloud
// with open sides, the AVX-512 build gives the scalar build's rows in the same order, a row over
// its capacity fails the build, and valid() tracks the skin.
#include "particles/neighbor_list.hpp"
#include "particles/simd.hpp"
#include "random_cloud.hpp"

#include <catch2/catch.hpp>

#include <algorithm>

using namespace fsi;
using namespace fsi::particles;

namespace {

/// Rows of the scalar and vector builds for a random cloud of n particles in [0, side]^D.
template <int D> void check_rows(std::size_t n, double side, double radius) {
  INFO("AVX-512 on this CPU: " << avx512_available());
  BasicNeighborList<D> scalar, vector;
  const test::Cloud<D> c = test::random_cloud<D>(n, side, 17);
  const BasicCellGrid<D> grid = test::binned_grid<D>(c, side, radius);
  REQUIRE(scalar.build(grid, c.coords(), n, radius, 128, false));
  REQUIRE(vector.build(grid, c.coords(), n, radius, 128, true));
  std::size_t pairs = 0, most = 0;
  for (std::size_t i = 0; i < n; ++i) {
    REQUIRE(vector.count(i) == scalar.count(i));
    CHECK(std::equal(scalar.row(i), scalar.row(i) + scalar.count(i), vector.row(i)));
    std::vector<std::uint32_t> row(scalar.row(i), scalar.row(i) + scalar.count(i));
    std::sort(row.begin(), row.end());
    REQUIRE(row == test::brute_force<D>(c, c.at(i), radius, i));
    pairs += row.size();
    most = std::max(most, row.size());
  }
  CHECK(pairs > 5 * n);
  // A row over its capacity fails both builds.
  CHECK_FALSE(scalar.build(grid, c.coords(), n, radius, most - 1, false));
  CHECK_FALSE(vector.build(grid, c.coords(), n, radius, most - 1, true));
}

} // namespace

TEST_CASE("particles: the 3-D neighbour list's rows are the pairs within the radius, scalar and "
          "AVX-512 builds alike",
          "[particles]") {
  check_rows<3>(4000, 0.3, 0.04);
}

TEST_CASE("particles: the 2-D neighbour list's rows are the pairs within the radius, scalar and "
          "AVX-512 builds alike",
          "[particles]") {
  check_rows<2>(3000, 0.4, 0.035);
}

TEST_CASE("particles: the 3-D neighbour list stays valid while every particle is within half the "
          "skin of its build position",
          "[particles]") {
  test::Cloud<3> c = test::random_cloud<3>(500, 0.3, 21);
  const BasicCellGrid<3> grid = test::binned_grid<3>(c, 0.3, 0.05);
  BasicNeighborList<3> list;
  REQUIRE(list.build(grid, c.coords(), c.size(), 0.05, 128));
  CHECK(list.build_positions(2) == c.x[2]);
  const double half_skin = 0.01;
  c.x[2][123] += 0.9 * half_skin; // along z only: the z distance counts
  CHECK(list.valid(c.coords(), c.size(), half_skin));
  c.x[2][123] += 0.2 * half_skin;
  CHECK_FALSE(list.valid(c.coords(), c.size(), half_skin));
  list.invalidate();
  CHECK_FALSE(list.valid(c.coords(), c.size(), half_skin));
}
