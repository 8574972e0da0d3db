// The AVX-512 kernels against their scalar forms and against the sums written out: the EMPS pair
// sums (pair_sums.hpp, the artificial viscosity's closing pairs with them) on a random cloud whose
// rows have every length modulo 8, a coincident pair (r = 0, left out of the gradient and the
// closing pairs) and pairs beyond r_e (left out of all three); the neighbour-list build
// (particles/neighbor_list.hpp).
#include "fluid_emps/pair_sums.hpp"
#include "particles/cell_grid.hpp"
#include "particles/neighbor_list.hpp"
#include "particles/simd.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

using namespace fsi;

TEST_CASE("emps pair sums: the AVX-512 and scalar forms equal the sums written out to round-off",
          "[fluid_emps]") {
  const double l0 = 0.01, r_e = 3.1 * l0, reach = 1.15 * r_e;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 12 * l0), v(-1.0, 1.0);
  const std::size_t n = 300;
  std::vector<double> x(n), y(n), vx(n), vy(n), p(n);
  for (std::size_t i = 0; i < n; ++i)
    x[i] = u(rng), y[i] = u(rng), vx[i] = v(rng), vy[i] = v(rng), p[i] = 1e4 * v(rng);
  x[1] = x[0], y[1] = y[0]; // a coincident pair
  INFO("AVX-512 on this CPU: " << particles::avx512_available());
  std::vector<std::uint32_t> row(n + 8);
  std::vector<bool> tail_lengths(8, false);
  double worst = 0.0, closing_sums = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    std::uint32_t c = 0;
    for (std::size_t j = 0; j < n; ++j)
      if (j != i && std::hypot(x[j] - x[i], y[j] - y[i]) < reach)
        row[c++] = static_cast<std::uint32_t>(j);
    for (std::size_t k = c; k < row.size(); ++k) row[k] = 0x7ffffff0u; // beyond the row: unread
    tail_lengths[c % 8] = true;
    // The sums written out (eqs. 9-11 without their constant factors).
    double pnd = 0, gx = 0, gy = 0, lx = 0, ly = 0, ax = 0, ay = 0;
    std::uint32_t within = 0;
    for (std::uint32_t k = 0; k < c; ++k) {
      const std::uint32_t j = row[k];
      const double dx = x[j] - x[i], dy = y[j] - y[i], r = std::hypot(dx, dy);
      if (r >= r_e) continue;
      const double w = (1 - r / r_e) * (1 - r / r_e);
      pnd += w, ++within;
      lx += (vx[j] - vx[i]) * w, ly += (vy[j] - vy[i]) * w;
      if (r > 0) gx += (p[j] + p[i]) * w * dx / (r * r), gy += (p[j] + p[i]) * w * dy / (r * r);
      // the closing pairs' sum ((v_j - v_i) . e) e w, e the unit vector from i to j
      const double closing = r > 0 ? ((vx[j] - vx[i]) * dx + (vy[j] - vy[i]) * dy) / r : 0.0;
      if (closing < 0) ax += closing * w * dx / r, ay += closing * w * dy / r;
    }
    closing_sums += std::hypot(ax, ay);
    const emps::PairRow pr{row.data(), c, {x[i], y[i]}, r_e * r_e, 1.0 / r_e};
    const emps::Coords<2> xy{x.data(), y.data()}, v{vx.data(), vy.data()};
    for (const bool vector : {false, true}) {
      const emps::PndSum d = emps::pnd_sum<2>(pr, xy, vector);
      const emps::VecSum<2> g = emps::gradient_sum<2>(pr, xy, p.data(), p[i], vector);
      const emps::VecSum<2> l = emps::laplacian_sum<2>(pr, xy, v, {vx[i], vy[i]}, vector);
      const emps::ViscousSum<2> a = emps::viscous_sum<2>(pr, xy, v, {vx[i], vy[i]}, vector);
      REQUIRE(d.within == within);
      // errors relative to the sums' scales: n0 ~ 4, |p| w / r ~ 1e4 / l0, |v| w ~ 1
      worst = std::max(
          {worst, std::abs(d.pnd - pnd) / 4.0, std::hypot(g[0] - gx, g[1] - gy) / (1e4 / l0),
           std::hypot(l[0] - lx, l[1] - ly), std::hypot(a.laplacian[0] - lx, a.laplacian[1] - ly),
           std::hypot(a.closing[0] - ax, a.closing[1] - ay)});
    }
  }
  for (int k = 0; k < 8; ++k) CHECK(tail_lengths[k]); // every row length modulo 8 occurred
  CHECK(closing_sums > static_cast<double>(n));       // the closing pairs' sums are not empty
  INFO("largest scaled difference " << worst);
  CHECK(worst < 1e-13);
}

TEST_CASE("particles: the AVX-512 neighbour-list build gives the scalar build's rows, in order, "
          "each the pairs within the radius",
          "[fluid_emps]") {
  const double radius = 0.035;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 0.4);
  const std::size_t n = 3000;
  std::vector<double> x(n), y(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = u(rng), y[i] = u(rng);
  x[1] = x[0], y[1] = y[0]; // a coincident pair
  particles::CellGrid grid(Vec2(0.0, 0.0), Vec2(0.4, 0.4), radius);
  grid.bin(x.data(), y.data(), n);
  INFO("AVX-512 on this CPU: " << particles::avx512_available());
  particles::NeighborList scalar, vector;
  REQUIRE(scalar.build(grid, x.data(), y.data(), n, radius, 128, false));
  REQUIRE(vector.build(grid, x.data(), y.data(), n, radius, 128, true));
  std::size_t pairs = 0;
  for (std::size_t i = 0; i < n; ++i) {
    REQUIRE(vector.count(i) == scalar.count(i));
    CHECK(std::equal(scalar.row(i), scalar.row(i) + scalar.count(i), vector.row(i)));
    std::size_t within = 0; // written out
    for (std::size_t j = 0; j < n; ++j)
      within +=
          j != i && (x[j] - x[i]) * (x[j] - x[i]) + (y[j] - y[i]) * (y[j] - y[i]) < radius * radius;
    CHECK(scalar.count(i) == within);
    pairs += within;
  }
  CHECK(pairs > 20 * n); // ~ pi r^2 n / area = 72 per particle
  // A row over its capacity fails both builds.
  CHECK_FALSE(scalar.build(grid, x.data(), y.data(), n, radius, 40, false));
  CHECK_FALSE(vector.build(grid, x.data(), y.data(), n, radius, 40, true));
}
