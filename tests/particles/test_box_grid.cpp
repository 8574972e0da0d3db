// The grid of boxes (particles/box_grid.hpp): the boxes the cells around a cube list hold every
// triangle within r of its centre, ascending and once each, against brute force.
#include "particles/box_grid.hpp"

#include "fsi/core/closest_on_triangle.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <random>

using namespace fsi;

TEST_CASE("box grid: the triangles near a point, as brute force finds them", "[particles][grid]") {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0), e(-0.04, 0.04);
  std::vector<std::array<Vec3, 3>> tri(3000);
  std::vector<particles::Box3d> boxes;
  for (auto& t : tri) {
    const Vec3 c(u(rng), u(rng), u(rng));
    for (auto& v : t) v = c + Vec3(e(rng), e(rng), e(rng));
    boxes.push_back({t[0].cwiseMin(t[1]).cwiseMin(t[2]), t[0].cwiseMax(t[1]).cwiseMax(t[2])});
  }
  particles::BoxGrid grid;
  grid.build(boxes, 0.05);
  CHECK(grid.dims()[0] >= 20);
  std::vector<int> near;
  std::size_t missing = 0, listed = 0, within = 0;
  for (int s = 0; s < 500; ++s) {
    const Vec3 q(1.4 * u(rng) - 0.2, 1.4 * u(rng) - 0.2, 1.4 * u(rng) - 0.2);
    const double r = 0.2 * u(rng);
    grid.overlapping(q - Vec3::Constant(r), q + Vec3::Constant(r), near);
    CHECK(std::is_sorted(near.begin(), near.end()));
    CHECK(std::adjacent_find(near.begin(), near.end()) == near.end());
    listed += near.size();
    for (std::size_t t = 0; t < tri.size(); ++t) {
      const auto& [a, b, c] = tri[t];
      if ((q - triangle_point(closest_on_triangle(q, a, b, c), a, b, c)).norm() > r) continue;
      ++within;
      missing += std::binary_search(near.begin(), near.end(), static_cast<int>(t)) ? 0 : 1;
    }
  }
  INFO(within << " triangles within r, " << listed << " listed");
  CHECK(within > 1000);
  CHECK(missing == 0);
  CHECK(listed < 20 * within); // a query lists the cells around it, not everything
}
