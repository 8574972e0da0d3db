// Lattice fill of a closed triangle surface (surface_fill.hpp): a cube whose face diagonals the
// rays meet exactly (the ties), and an octahedron against its inequality.
#include "geometry_erp/box_walls.hpp"
#include "geometry_erp/surface_fill.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace fsi;
using namespace fsi::erp;

TEST_CASE("erp: fill of a closed surface: a cube of 12 triangles holds its 10^3 lattice points",
          "[fill][3d]") {
  const double l0 = 0.02;
  const Vec3 lo(0.3, -0.1, 0.05), hi = lo + Vec3::Constant(10 * l0);
  TriangleWallSet box;
  add_box_tank(box, lo, hi, false, 0);
  // Rays along x at (y, z) = lo + ((j + 1/2) l0, (k + 1/2) l0) meet the faces x = lo.x, hi.x on
  // their diagonals where j = k (or j + k = 9): a tie counted twice or never would empty a row.
  const std::vector<Vec3> x = fill_closed_surface(box.nodes().x, box.triangles().node, l0);
  REQUIRE(x.size() == 1000);
  std::size_t n = 0;
  for (int k = 0; k < 10; ++k)
    for (int j = 0; j < 10; ++j)
      for (int i = 0; i < 10; ++i, ++n)
        CHECK((x[n] - (lo + l0 * Vec3(i + 0.5, j + 0.5, k + 0.5))).norm() == 0.0);
}

TEST_CASE("erp: fill of a closed surface: an octahedron holds the lattice points of |x| + |y| + "
          "|z| < R",
          "[fill][3d]") {
  const double l0 = 0.02, R = 0.1;
  const Vec3 c(0.2, 0.3, -0.1);
  const std::vector<Vec3> points = {c + R * Vec3::UnitX(), c - R * Vec3::UnitX(),
                                    c + R * Vec3::UnitY(), c - R * Vec3::UnitY(),
                                    c + R * Vec3::UnitZ(), c - R * Vec3::UnitZ()};
  std::vector<std::array<int, 3>> triangles;
  for (const int a : {0, 1})
    for (const int b : {2, 3})
      for (const int d : {4, 5}) triangles.push_back({a, b, d});
  const std::vector<Vec3> x = fill_closed_surface(points, triangles, l0);
  // The lattice c - R + (i + 1/2) l0 sits at odd multiples of l0/2 from c: |x| + |y| + |z| is
  // never R, while the rays meet the silhouette |y| + |z| = R (ties counted twice or never).
  std::size_t expected = 0;
  for (int k = 0; k < 10; ++k)
    for (int j = 0; j < 10; ++j)
      for (int i = 0; i < 10; ++i) {
        const Vec3 r = l0 * Vec3(i + 0.5, j + 0.5, k + 0.5) - Vec3::Constant(R);
        expected += r.cwiseAbs().sum() < R;
      }
  CHECK(expected == 8 * 20); // 20 positive odd triples (p, q, r) with p + q + r < 10
  CHECK(x.size() == expected);
  for (const Vec3& p : x) CHECK((p - c).cwiseAbs().sum() < R);
}
