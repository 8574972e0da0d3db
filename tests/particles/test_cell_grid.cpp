// The D-dimensional cell grid: the 3^D block around a point holds every particle within the cell
// side (against a brute-force search on a random cloud with open sides), each once, and the
// binning is sorted by cell with x fastest.
#include "particles/cell_grid.hpp"
#include "random_cloud.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <limits>

using namespace fsi;
using namespace fsi::particles;

namespace {

/// For query points at the particles and at points all over and around the box: the particles
/// found in the block within h are exactly the brute-force set, and no particle is found twice.
template <int D> void check_against_brute_force(std::size_t n, double side, double h) {
  const test::Cloud<D> c = test::random_cloud<D>(n, side, 5);
  const BasicCellGrid<D> grid = test::binned_grid<D>(c, side, h);
  const test::Cloud<D> queries = test::random_cloud<D>(200, side, 9);
  const auto none = std::numeric_limits<std::size_t>::max();
  std::size_t total = 0;
  for (std::size_t q = 0; q < n + queries.size(); ++q) {
    const VecD<D> p = q < n ? c.at(q) : queries.at(q - n);
    std::vector<std::uint32_t> found, seen;
    grid.for_each_near(p, [&](std::uint32_t j) {
      seen.push_back(j);
      if (j != q && (c.at(j) - p).squaredNorm() < h * h) found.push_back(j);
    });
    std::sort(found.begin(), found.end());
    std::sort(seen.begin(), seen.end());
    REQUIRE(std::adjacent_find(seen.begin(), seen.end()) == seen.end());
    REQUIRE(found == test::brute_force<D>(c, p, h, q < n ? q : none));
    total += found.size();
  }
  CHECK(total > 5 * n); // the cloud is dense enough for the test to mean something
}

} // namespace

TEST_CASE("particles: the 3-D cell grid's 3 x 3 x 3 block holds every particle within h, each once",
          "[particles]") {
  check_against_brute_force<3>(3000, 0.3, 0.04);
}

TEST_CASE("particles: the 2-D cell grid's 3 x 3 block holds every particle within h, each once",
          "[particles]") {
  check_against_brute_force<2>(3000, 0.4, 0.035);
}

TEST_CASE("particles: the 3-D binning is sorted by cell, x fastest, then y, then z",
          "[particles]") {
  const double side = 0.3, h = 0.04;
  const test::Cloud<3> c = test::random_cloud<3>(2000, side, 3);
  const BasicCellGrid<3> grid = test::binned_grid<3>(c, side, h);
  CHECK(grid.cells(0) == 11); // ceil(0.3 / 0.04) + 3 = 11 along each axis
  CHECK(grid.cells(2) == 11);
  const auto cell_of = [&](std::uint32_t j) {
    const Vec3 p = c.at(j);
    return (grid.cell(2, p.z()) * grid.ny() + grid.cell_y(p.y())) * grid.nx() + grid.cell_x(p.x());
  };
  const auto& order = grid.order();
  REQUIRE(order.size() == c.size());
  for (std::size_t k = 1; k < order.size(); ++k) {
    CHECK(cell_of(order[k - 1]) <= cell_of(order[k]));
    if (cell_of(order[k - 1]) == cell_of(order[k])) CHECK(order[k - 1] < order[k]); // stable
  }
  // A row's cells are one contiguous range: begin(nx, row) is the next row's begin(0, .).
  for (int row = 0; row + 1 < grid.ny() * grid.cells(2); ++row)
    CHECK(grid.begin(grid.nx(), row) == grid.begin(0, row + 1));
}

TEST_CASE("particles: the 2-D grid's (x, y) interface is the generic one", "[particles]") {
  const test::Cloud<2> c = test::random_cloud<2>(1000, 0.4, 4);
  CellGrid a(Vec2::Zero(), Vec2::Constant(0.4), 0.035), b = a;
  a.bin(c.x[0].data(), c.x[1].data(), c.size());
  b.bin(c.coords(), c.size());
  CHECK(a.order() == b.order());
  for (std::size_t i = 0; i < c.size(); i += 37) {
    std::vector<std::uint32_t> ja, jb;
    a.for_each_near(c.x[0][i], c.x[1][i], [&](std::uint32_t j) { ja.push_back(j); });
    b.for_each_near(c.at(i), [&](std::uint32_t j) { jb.push_back(j); });
    CHECK(ja == jb);
  }
}
