// The D-dimensional periodic grid: with periodic and open sides mixed, the wrapped 3^D block around
// a point holds, for every particle whose nearest image is within the cell side, that image (the
// right shift), once; against a brute-force search over the images on a random cloud.
#include "particles/periodic_grid.hpp"
#include "random_cloud.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

using namespace fsi;
using namespace fsi::particles;

namespace {

/// The shift s (0 or +-L_a per axis) that brings x_j nearest to p: along periodic axes only.
template <int D>
VecD<D> nearest_image_shift(const VecD<D>& xj, const VecD<D>& p, const VecD<D>& L,
                            const std::array<bool, D>& periodic) {
  VecD<D> s = VecD<D>::Zero();
  for (int a = 0; a < D; ++a)
    if (periodic[static_cast<std::size_t>(a)])
      for (const double t : {-L[a], L[a]})
        if (std::abs(xj[a] + t - p[a]) < std::abs(xj[a] + s[a] - p[a])) s[a] = t;
  return s;
}

template <int D>
void check_periodic(std::size_t n, double side, double cell, const std::array<bool, D>& periodic) {
  test::Cloud<D> c = test::random_cloud<D>(n, side, 13);
  BasicPeriodicGrid<D> grid(VecD<D>::Zero(), VecD<D>::Constant(side), cell, periodic);
  for (std::size_t a = 0; a < D; ++a)
    for (double& v : c.x[a]) v = grid.wrap(static_cast<int>(a), v);
  grid.bin(c.coords(), n);
  const VecD<D> L = VecD<D>::Constant(side);
  std::size_t total = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const VecD<D> p = c.at(i);
    std::vector<std::pair<std::uint32_t, VecD<D>>> found;
    std::vector<std::uint32_t> seen;
    grid.for_each_near(p, [&](std::uint32_t j, const std::array<double, D>& s) {
      seen.push_back(j);
      VecD<D> shift;
      for (int a = 0; a < D; ++a) shift[a] = s[static_cast<std::size_t>(a)];
      if (j != i && (c.at(j) + shift - p).norm() < cell) found.emplace_back(j, shift);
    });
    std::sort(seen.begin(), seen.end());
    REQUIRE(std::adjacent_find(seen.begin(), seen.end()) == seen.end());
    std::sort(found.begin(), found.end(),
              [](const auto& u, const auto& v) { return u.first < v.first; });
    std::vector<std::pair<std::uint32_t, VecD<D>>> expected;
    for (std::size_t j = 0; j < n; ++j) {
      const VecD<D> s = nearest_image_shift<D>(c.at(j), p, L, periodic);
      if (j != i && (c.at(j) + s - p).norm() < cell)
        expected.emplace_back(static_cast<std::uint32_t>(j), s);
    }
    REQUIRE(found.size() == expected.size());
    for (std::size_t k = 0; k < found.size(); ++k) {
      REQUIRE(found[k].first == expected[k].first);
      REQUIRE(found[k].second == expected[k].second);
    }
    total += found.size();
  }
  CHECK(total > 5 * n);
}

} // namespace

TEST_CASE("particles: the 3-D periodic grid finds every nearest image within the cell side, with "
          "periodic x and z and an open y",
          "[particles]") {
  check_periodic<3>(3000, 0.2, 0.045, {true, false, true});
  check_periodic<3>(3000, 0.2, 0.045, {true, true, true});
}

TEST_CASE("particles: the 2-D periodic grid finds every nearest image within the cell side, and "
          "its (x, y) form is the generic one",
          "[particles]") {
  check_periodic<2>(2000, 0.3, 0.035, {true, false});
  const test::Cloud<2> c = test::random_cloud<2>(500, 0.3, 2);
  PeriodicGrid grid(Vec2::Zero(), Vec2::Constant(0.3), 0.035, false, true);
  grid.bin(c.x[0].data(), c.x[1].data(), c.size());
  for (std::size_t i = 0; i < c.size(); i += 23) {
    std::vector<std::array<double, 3>> a, b;
    grid.for_each_near(c.x[0][i], c.x[1][i], [&](std::uint32_t j, double sx, double sy) {
      a.push_back({double(j), sx, sy});
    });
    grid.for_each_near(c.at(i), [&](std::uint32_t j, const std::array<double, 2>& s) {
      b.push_back({double(j), s[0], s[1]});
    });
    CHECK(a == b);
  }
}

TEST_CASE("particles: a periodic direction needs three cells in 3-D", "[particles]") {
  CHECK_THROWS_AS(
      BasicPeriodicGrid<3>(Vec3::Zero(), Vec3(1.0, 1.0, 0.25), 0.1, {false, false, true}),
      std::invalid_argument);
}
