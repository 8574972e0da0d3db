// Triangle walls (TriangleWallSet) and the 3-D nearest-triangle query (TriangleLocator, eqs.
// 18-19) against a brute-force search over all triangles written independently here.
#include "geometry_erp/triangle_locator.hpp"

#include "fsi/core/error.hpp"
#include "fsi/core/parallel.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <random>
#include <span>
#include <vector>

using namespace fsi;
using namespace fsi::erp;
using Catch::Matchers::WithinAbs;
using Tri = std::array<int, 3>;

namespace {

double segment_distance2(const Vec3& p, const Vec3& a, const Vec3& b) {
  const double t = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
  return (p - (a + t * (b - a))).squaredNorm();
}

/// Squared distance from p to triangle abc: the projection onto the plane if it falls inside,
/// else the nearest of the three edges.
double triangle_distance2(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 n = (b - a).cross(c - a);
  const Vec3 q = p - (p - a).dot(n) / n.squaredNorm() * n;
  if ((b - a).cross(q - a).dot(n) >= 0.0 && (c - b).cross(q - b).dot(n) >= 0.0 &&
      (a - c).cross(q - c).dot(n) >= 0.0)
    return (p - q).squaredNorm();
  return std::min(
      {segment_distance2(p, a, b), segment_distance2(p, b, c), segment_distance2(p, c, a)});
}

double distance2_to(const TriangleWallSet& walls, int t, const Vec3& p) {
  const auto& abc = walls.triangles().node[static_cast<std::size_t>(t)];
  const auto& x = walls.nodes().x;
  return triangle_distance2(p, x[static_cast<std::size_t>(abc[0])],
                            x[static_cast<std::size_t>(abc[1])],
                            x[static_cast<std::size_t>(abc[2])]);
}

/// The unit cube [0, 1]^3 as 12 triangles, normals out (an obstacle) or in (a tank).
void add_cube(TriangleWallSet& walls, bool fluid_inside) {
  std::vector<Vec3> corners;
  for (int k = 0; k < 8; ++k) corners.emplace_back(k & 1, (k >> 1) & 1, (k >> 2) & 1);
  std::vector<Tri> tris;
  for (int d = 0; d < 3; ++d)
    for (int side = 0; side < 2; ++side) {
      // Corners p(u, v) of the face x_d = side, u along axis d + 1, v along d + 2: the normal
      // of (p10 - p00) x (p01 - p00) is +e_d.
      const auto p = [&](int u, int v) {
        return (side << d) | (u << ((d + 1) % 3)) | (v << ((d + 2) % 3));
      };
      const bool along = (side == 1) != fluid_inside; // wanted normal +e_d
      if (along)
        tris.insert(tris.end(), {{p(0, 0), p(1, 0), p(1, 1)}, {p(0, 0), p(1, 1), p(0, 1)}});
      else
        tris.insert(tris.end(), {{p(0, 0), p(1, 1), p(1, 0)}, {p(0, 0), p(0, 1), p(1, 1)}});
    }
  walls.add_triangles(corners, tris, 0);
}

constexpr int arc_cells = 12, height_cells = 6;

/// A quarter-cylinder patch of radius 1 about the z axis, angle 0..pi/2, z in [0, 1]; the fluid on
/// the axis side.
void add_quarter_cylinder(TriangleWallSet& walls) {
  std::vector<Vec3> points;
  for (int j = 0; j <= height_cells; ++j)
    for (int i = 0; i <= arc_cells; ++i) {
      const double theta = 0.5 * std::numbers::pi * i / arc_cells;
      points.emplace_back(std::cos(theta), std::sin(theta), double(j) / height_cells);
    }
  std::vector<Tri> tris;
  const auto id = [](int i, int j) { return j * (arc_cells + 1) + i; };
  for (int j = 0; j < height_cells; ++j)
    for (int i = 0; i < arc_cells; ++i) // (p10 - p00) x (p01 - p00) points out: reversed
      tris.insert(tris.end(), {{id(i, j), id(i + 1, j + 1), id(i + 1, j)},
                               {id(i, j), id(i, j + 1), id(i + 1, j + 1)}});
  walls.add_triangles(points, tris, 3);
}

/// Fluid side of the patch for a point whose nearest wall point is not on its border: on the
/// axis side of every chord of the arc in the xy plane (the region they bound is convex).
bool inside_arc(const TriangleWallSet& walls, const Vec3& p) {
  const auto& x = walls.nodes().x;
  for (int i = 0; i < arc_cells; ++i) {
    const Vec3 a = x[static_cast<std::size_t>(i)], b = x[static_cast<std::size_t>(i + 1)];
    if ((b.x() - a.x()) * (p.y() - a.y()) - (b.y() - a.y()) * (p.x() - a.x()) < 0.0) return false;
  }
  return true;
}

/// Distance^2 from p to the patch's border (the four sides of its parameter rectangle).
double border_distance2(const TriangleWallSet& walls, const Vec3& p) {
  const auto& x = walls.nodes().x;
  const auto at = [&](int i, int j) {
    return x[static_cast<std::size_t>(j * (arc_cells + 1) + i)];
  };
  double d2 = std::numeric_limits<double>::infinity();
  for (int i = 0; i < arc_cells; ++i)
    for (const int j : {0, height_cells})
      d2 = std::min(d2, segment_distance2(p, at(i, j), at(i + 1, j)));
  for (int j = 0; j < height_cells; ++j)
    for (const int i : {0, arc_cells})
      d2 = std::min(d2, segment_distance2(p, at(i, j), at(i, j + 1)));
  return d2;
}

struct Counts {
  int hits = 0, crossed = 0, ties = 0;
};

/// Every point of a random cloud in [lo, hi]^3: hit iff within r_e by brute force, the same
/// triangle (or an equally near one), distance to 1e-14, x_wall on the wall at distance r, and
/// crossed == expect_crossed(p, d2) for the hits.
Counts check_cloud(const TriangleWallSet& walls, double r_e, double lo, double hi,
                   const std::function<bool(const Vec3&, double)>& expect_crossed) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(lo, hi);
  std::vector<Vec3> x(5000);
  for (Vec3& p : x) p = Vec3(u(rng), u(rng), u(rng));
  const TriangleLocator locator(walls, r_e);
  TriangleHits hits;
  locator.query(x, hits);
  Counts counts;
  for (std::size_t i = 0; i < x.size(); ++i) {
    int best = -1;
    double d2 = r_e * r_e;
    for (int t = 0; t < static_cast<int>(walls.triangles().size()); ++t)
      if (const double e2 = distance2_to(walls, t, x[i]); e2 < d2) best = t, d2 = e2;
    INFO("point " << i << " at " << x[i].transpose());
    REQUIRE((hits.triangle[i] >= 0) == (best >= 0));
    if (best < 0) {
      CHECK(hits.r[i] == std::numeric_limits<double>::infinity());
      continue;
    }
    ++counts.hits;
    if (hits.triangle[i] != best) {
      ++counts.ties;
      REQUIRE_THAT(std::sqrt(distance2_to(walls, hits.triangle[i], x[i])),
                   WithinAbs(std::sqrt(d2), 1e-14));
    }
    REQUIRE_THAT(hits.r[i], WithinAbs(std::sqrt(d2), 1e-14));
    REQUIRE_THAT((x[i] - hits.x_wall[i]).norm(), WithinAbs(hits.r[i], 1e-15));
    REQUIRE_THAT(hits.bary[i].sum(), WithinAbs(1.0, 1e-14));
    REQUIRE(hits.bary[i].minCoeff() >= -1e-14);
    REQUIRE_THAT(hits.n_wall[i].norm(), WithinAbs(1.0, 1e-14));
    REQUIRE(bool(hits.crossed[i]) == expect_crossed(x[i], d2));
    counts.crossed += hits.crossed[i];
  }
  return counts;
}

bool in_unit_cube(const Vec3& p) {
  return (p.array() >= 0.0).all() && (p.array() <= 1.0).all();
}

} // namespace

TEST_CASE("erp: triangle walls reject bad indices and degenerate triangles", "[triangle_walls]") {
  TriangleWallSet walls;
  const std::vector<Vec3> p{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(2, 0, 0)};
  CHECK_THROWS_AS(walls.add_triangles(p, std::vector<Tri>{{0, 1, 4}}, 0), InputError);
  CHECK_THROWS_AS(walls.add_triangles(p, std::vector<Tri>{{0, -1, 2}}, 0), InputError);
  CHECK_THROWS_AS(walls.add_triangles(p, std::vector<Tri>{{0, 1, 1}}, 0), InputError);
  CHECK_THROWS_AS(walls.add_triangles(p, std::vector<Tri>{{0, 1, 3}}, 0), InputError); // collinear
  CHECK(walls.triangles().size() == 0);
  CHECK(walls.nodes().size() == 0);
  const TriangleRange range = walls.add_triangles(p, std::vector<Tri>{{0, 1, 2}}, 7);
  CHECK(range.node_count == 4);
  CHECK(range.triangle_count == 1);
  CHECK(walls.triangles().group[0] == 7);
  CHECK(walls.face_normal(0) == Vec3(0, 0, 1));
  CHECK(walls.open(0, TriangleFeature::edge_ab));
  CHECK(walls.open(0, TriangleFeature::vertex_c));
  CHECK_FALSE(walls.open(0, TriangleFeature::face));
}

TEST_CASE("erp: a wide flat triangle wall gets cells larger than r_e, at most 2^22",
          "[triangle_walls]") {
  TriangleWallSet walls;
  const std::vector<Vec3> p{Vec3(0, 0, 0), Vec3(1000, 0, 0), Vec3(1000, 1000, 0), Vec3(0, 1000, 0)};
  walls.add_triangles(p, std::vector<Tri>{{0, 1, 2}, {0, 2, 3}}, 0);
  const TriangleLocator locator(walls, 0.01);
  const double h = locator.cell_size();
  CHECK(h > 0.01);
  CHECK((std::floor(1000.0 / h) + 1.0) * (std::floor(1000.0 / h) + 1.0) <= double(1 << 22));
  const std::vector<Vec3> x{Vec3(500.25, 200.75, 0.004), Vec3(500.25, 200.75, 0.02),
                            Vec3(999.5, 0.5, -0.005)};
  TriangleHits hits;
  locator.query(x, hits);
  CHECK(hits.triangle[0] == 0);
  CHECK_THAT(hits.r[0], WithinAbs(0.004, 1e-12));
  CHECK(hits.triangle[1] == -1);
  CHECK(hits.crossed[2]); // below the wall, under its interior
}

TEST_CASE("erp: pseudo-normals of a closed cube tank at its edges and vertices",
          "[triangle_walls]") {
  TriangleWallSet walls;
  add_cube(walls, true);
  for (int t = 0; t < 12; ++t)
    for (int f = 0; f < 7; ++f) CHECK_FALSE(walls.open(t, static_cast<TriangleFeature>(f)));
  const TriangleLocator locator(walls, 0.15);
  const std::vector<Vec3> x{Vec3(0, 0, 0.5),         Vec3(0, 0, 0), // on an edge, a vertex
                            Vec3(-0.01, -0.01, 0.5), Vec3(-0.01, -0.01, -0.01), // just outside
                            Vec3(0.01, 0.01, 0.5),   Vec3(0.01, 0.02, 0.03)};   // just inside
  TriangleHits hits;
  locator.query(x, hits);
  const double s2 = std::sqrt(0.5), s3 = std::sqrt(1.0 / 3.0);
  CHECK(hits.r[0] == 0.0);
  CHECK(int(hits.feature[0]) >= int(TriangleFeature::edge_ab));
  CHECK((hits.n_wall[0] - Vec3(s2, s2, 0)).norm() < 1e-15);
  CHECK(hits.r[1] == 0.0);
  CHECK(int(hits.feature[1]) <= int(TriangleFeature::vertex_c));
  CHECK((hits.n_wall[1] - Vec3(s3, s3, s3)).norm() < 1e-15);
  CHECK_FALSE(hits.crossed[0]);
  CHECK_FALSE(hits.crossed[1]);
  CHECK(hits.crossed[2]);
  CHECK((hits.n_wall[2] - Vec3(-s2, -s2, 0)).norm() < 1e-14);
  CHECK(hits.crossed[3]);
  CHECK(int(hits.feature[3]) <= int(TriangleFeature::vertex_c));
  CHECK_FALSE(hits.crossed[4]);
  CHECK_THAT(hits.r[4], WithinAbs(0.01, 1e-15));
  CHECK_FALSE(hits.crossed[5]);
  CHECK((hits.n_wall[5] - Vec3(1, 0, 0)).norm() < 1e-15); // the face x = 0
}

TEST_CASE("erp: nearest triangle of a cube tank (fluid inside) and a box obstacle (fluid "
          "outside) matches brute force",
          "[triangle_walls]") {
  for (const bool fluid_inside : {true, false}) {
    TriangleWallSet walls;
    add_cube(walls, fluid_inside);
    const Counts c = check_cloud(walls, 0.15, -0.2, 1.2, [&](const Vec3& p, double) {
      return in_unit_cube(p) != fluid_inside;
    });
    CHECK(c.hits > 2000);
    CHECK(c.crossed > 500);
  }
}

TEST_CASE("erp: nearest triangle of an open quarter-cylinder patch matches brute force",
          "[triangle_walls]") {
  TriangleWallSet walls;
  add_quarter_cylinder(walls);
  int open_edges = 0;
  for (int t = 0; t < static_cast<int>(walls.triangles().size()); ++t)
    for (const auto f :
         {TriangleFeature::edge_ab, TriangleFeature::edge_bc, TriangleFeature::edge_ca})
      open_edges += walls.open(t, f);
  CHECK(open_edges == 2 * (arc_cells + height_cells));
  // Crossed only with the nearest point off the border and the point outside the arc.
  const Counts c = check_cloud(walls, 0.15, -0.2, 1.2, [&](const Vec3& p, double d2) {
    return border_distance2(walls, p) > d2 * (1.0 + 1e-12) && !inside_arc(walls, p);
  });
  CHECK(c.hits > 500);
  CHECK(c.crossed > 100);
}

TEST_CASE("erp: triangle queries follow moving nodes and do not depend on the thread count",
          "[triangle_walls]") {
  TriangleWallSet walls;
  add_quarter_cylinder(walls);
  add_cube(walls, false);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-0.2, 1.2);
  std::vector<Vec3> x(4000);
  for (Vec3& p : x) p = Vec3(u(rng), u(rng), u(rng));
  TriangleLocator locator(walls, 0.15);
  TriangleHits before, moved, one_thread;
  locator.query(x, before);
  const Vec3 shift(0.3, -0.2, 0.1), v(1.0, 2.0, 3.0);
  for (std::size_t L = 0; L < walls.nodes().size(); ++L) {
    walls.nodes().x[L] += shift;
    walls.nodes().v[L] = v;
  }
  walls.update();
  locator.update();
  for (Vec3& p : x) p += shift;
  locator.query(x, moved);
  set_sequential(true);
  locator.query(x, one_thread);
  set_sequential(false);
  std::vector<double> xs, ys, zs; // the same points as coordinate arrays
  for (const Vec3& p : x) xs.push_back(p.x()), ys.push_back(p.y()), zs.push_back(p.z());
  TriangleHits arrays;
  locator.query(xs, ys, zs, arrays);
  int near = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    INFO("point " << i);
    REQUIRE(moved.triangle[i] == one_thread.triangle[i]);
    REQUIRE(moved.r[i] == one_thread.r[i]);
    REQUIRE(moved.crossed[i] == one_thread.crossed[i]);
    REQUIRE(moved.triangle[i] == arrays.triangle[i]);
    REQUIRE(moved.r[i] == arrays.r[i]);
    REQUIRE((moved.triangle[i] >= 0) == (before.triangle[i] >= 0));
    if (moved.triangle[i] < 0) continue;
    ++near;
    REQUIRE_THAT(moved.r[i], WithinAbs(before.r[i], 1e-14));
    REQUIRE(moved.crossed[i] == before.crossed[i]);
    REQUIRE((moved.v_wall[i] - v).norm() < 1e-14);
  }
  CHECK(near > 1000);
}

TEST_CASE("erp: hits and convex pieces grown from a smaller query equal a fresh query's",
          "[triangle_walls]") {
  // A query writes every entry it reads (fsi::fresh_resize drops the old ones as the records
  // grow, docs/performance.md "Set-up memory per rank"): the 4000 points queried after 1000 others
  // into the same records give the records of a first query, bit for bit.
  TriangleWallSet walls;
  add_quarter_cylinder(walls);
  add_cube(walls, false); // a box obstacle: convex edges and corners
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-0.2, 1.2);
  std::vector<double> x(4000), y(4000), z(4000);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = u(rng), y[i] = u(rng), z[i] = u(rng);
  const TriangleLocator locator(walls, 0.15);
  REQUIRE(locator.has_convex_edges());
  const auto query = [&](std::size_t n, std::array<TriangleHits, 3>& faces, ConvexFaces& convex) {
    const std::span<const double> xs(x.data(), n), ys(y.data(), n), zs(z.data(), n);
    locator.query(xs, ys, zs, faces[0]);
    locator.corner_faces(xs, ys, zs, faces);
    locator.convex_faces(xs, ys, zs, faces, convex);
  };
  std::array<TriangleHits, 3> grown, fresh;
  ConvexFaces grown_convex, fresh_convex;
  query(1000, grown, grown_convex);
  query(x.size(), grown, grown_convex);
  query(x.size(), fresh, fresh_convex);
  int faces = 0, pieces = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    INFO("point " << i);
    for (std::size_t k = 0; k < 3; ++k) {
      const TriangleHits &g = grown[k], &f = fresh[k];
      REQUIRE(g.triangle[i] == f.triangle[i]);
      if (f.triangle[i] < 0) continue;
      ++faces;
      REQUIRE(g.feature[i] == f.feature[i]);
      REQUIRE(g.r[i] == f.r[i]);
      REQUIRE(g.crossed[i] == f.crossed[i]);
      REQUIRE(g.bary[i] == f.bary[i]);
      REQUIRE(g.x_wall[i] == f.x_wall[i]);
      REQUIRE(g.n_wall[i] == f.n_wall[i]);
      REQUIRE(g.v_wall[i] == f.v_wall[i]);
      REQUIRE(g.a_wall[i] == f.a_wall[i]);
    }
    REQUIRE(grown_convex.pieces[i] == fresh_convex.pieces[i]);
    for (std::size_t q = 0; q < fresh_convex.pieces[i]; ++q) {
      ++pieces;
      REQUIRE(grown_convex.face[q][i] == fresh_convex.face[q][i]);
      REQUIRE(grown_convex.seed[q][i] == fresh_convex.seed[q][i]);
      REQUIRE(grown_convex.bary[q][i] == fresh_convex.bary[q][i]);
      REQUIRE(grown_convex.end[q][i] == fresh_convex.end[q][i]);
      for (std::size_t m = fresh_convex.begin(q, i); m < fresh_convex.end[q][i]; ++m) {
        REQUIRE(grown_convex.n[m][i] == fresh_convex.n[m][i]);
        REQUIRE(grown_convex.s[m][i] == fresh_convex.s[m][i]);
      }
    }
  }
  CHECK(faces > 1000);
  CHECK(pieces > 100);
}
