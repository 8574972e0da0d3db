// The lattice of a box's wedge (region_lattice_sum3) against the lattice counted point by point,
// and the convex faces a box obstacle gives its neighbours (TriangleLocator::convex_faces).
#include "geometry_erp/box_walls.hpp"
#include "geometry_erp/convex_wedge3.hpp"
#include "geometry_erp/triangle_locator.hpp"

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <vector>

using namespace fsi;
using namespace fsi::erp;

namespace {

/// Both sums over the lattice points x_i + l0 (i, j, k) inside the octant x, y, z < 0 (its
/// `axes` first axes bounded, the others free), the particle at x_i.
LatticeSum3 octant_direct(const Vec3& x_i, int axes, double l0, double r_e,
                          const particles::MpsWeight& w) {
  LatticeSum3 sum;
  const int n = static_cast<int>(std::ceil(r_e / l0));
  for (int k = -n; k <= n; ++k)
    for (int j = -n; j <= n; ++j)
      for (int i = -n; i <= n; ++i) {
        const Vec3 d = l0 * Vec3(i, j, k), x = x_i + d;
        bool in = true;
        for (int a = 0; a < axes; ++a) in = in && x[a] < 0.0;
        const double r2 = d.squaredNorm();
        if (!in || r2 == 0.0 || r2 >= r_e * r_e) continue;
        sum.weight += w(std::sqrt(r2));
        sum.gradient += w(std::sqrt(r2)) / r2 * d;
      }
  return sum;
}

} // namespace

TEST_CASE("region_lattice_sum3: a box's edge and corner wedge equals its lattice counted directly "
          "from every lattice site within r_e, inside or outside each half-space",
          "[convex3d]") {
  const double l0 = 0.01, r_e = 3.1 * l0;
  const particles::MpsWeight w(r_e);
  const Vec3 e[3] = {Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ()};
  double worst = 0.0;
  int cases = 0;
  for (int axes = 1; axes <= 3; ++axes)
    for (int k = -4; k < 4; ++k)
      for (int j = -4; j < 4; ++j)
        for (int i = -4; i < 4; ++i) {
          const Vec3 x = l0 * Vec3(i + 0.5, j + 0.5, k + 0.5); // the faces at 0, between rows
          bool outside = false;
          for (int a = 0; a < axes; ++a) outside = outside || x[a] > 0.0;
          if (!outside) continue; // a fluid particle: outside the solid octant
          std::vector<HalfSpace3> region;
          for (int a = 0; a < axes; ++a) region.push_back({e[a], x[a]}); // s = signed distance
          const auto sum = region_lattice_sum3(region, l0, r_e, w);
          REQUIRE(sum.has_value());
          const LatticeSum3 direct = octant_direct(x, axes, l0, r_e, w);
          worst = std::max({worst, std::abs(sum->weight - direct.weight),
                            (sum->gradient - direct.gradient).norm() * l0});
          ++cases;
        }
  INFO(cases << " sites, worst difference " << worst);
  CHECK(cases > 1000);
  CHECK(worst < 1e-12);
}

TEST_CASE("region_lattice_sum3: a box narrower than r_e counted directly; equal half-spaces "
          "merge, disjoint opposite ones are empty, planes that are not a box's are refused",
          "[convex3d]") {
  const double l0 = 0.01, r_e = 3.1 * l0;
  const particles::MpsWeight w(r_e);
  // A 2 x 3 x 1 l0 box (rows 0..1, 0..2, 0 from its corner) beside the particle at the origin.
  const Vec3 lo(0.5, -1.5, -0.5), hi(2.5, 1.5, 0.5); // in l0, faces between rows
  const HalfSpace3 box[6] = {{-Vec3::UnitX(), lo[0] * l0}, {Vec3::UnitX(), -hi[0] * l0},
                             {-Vec3::UnitY(), lo[1] * l0}, {Vec3::UnitY(), -hi[1] * l0},
                             {-Vec3::UnitZ(), lo[2] * l0}, {Vec3::UnitZ(), -hi[2] * l0}};
  double direct = 0.0;
  Vec3 direct_g = Vec3::Zero();
  for (int i = 1; i <= 2; ++i)
    for (int j = -1; j <= 1; ++j) {
      const Vec3 d = l0 * Vec3(i, j, 0);
      direct += w(d.norm()), direct_g += w(d.norm()) / d.squaredNorm() * d;
    }
  const auto small = region_lattice_sum3(box, l0, r_e, w);
  REQUIRE(small.has_value());
  CHECK(std::abs(small->weight - direct) < 1e-12);
  CHECK((small->gradient - direct_g).norm() * l0 < 1e-12);
  const HalfSpace3 floor{Vec3::UnitZ(), 0.5 * l0}, side{Vec3::UnitX(), 1.5 * l0};
  const HalfSpace3 twice[3] = {floor, side, floor}; // a box's bottom on the floor's plane
  const HalfSpace3 once[2] = {floor, side};
  CHECK(region_lattice_sum3(twice, l0, r_e, w)->weight ==
        region_lattice_sum3(once, l0, r_e, w)->weight);
  CHECK(region_lattice_sum3(once, l0, r_e, w)->weight > 0.0);
  const HalfSpace3 slab[2] = {floor, {-Vec3::UnitZ(), -0.5 * l0}}; // below and above z = 0
  CHECK(region_lattice_sum3(slab, l0, r_e, w)->weight == 0.0);
  const HalfSpace3 skew[2] = {floor, {Vec3(1.0, 0.0, 1.0).normalized(), l0}};
  CHECK_FALSE(region_lattice_sum3(skew, l0, r_e, w).has_value());
}

TEST_CASE("convex_faces: none beside a face or in a tank's concave corner, one beside a box's "
          "edge, two beside its corner",
          "[convex3d]") {
  const double l0 = 0.01, r_e = 3.1 * l0;
  TriangleWallSet walls;
  add_box_tank(walls, Vec3::Zero(), Vec3::Constant(0.2), false, 0);
  add_box_obstacle(walls, Vec3::Constant(0.04), Vec3::Constant(0.12), 1); // wider than 2 r_e
  const TriangleLocator locator(walls, r_e);
  // Beside the face x = 0.12 (middle), its edge with y = 0.12, the corner, a tank corner.
  const std::vector<Vec3> x = {
      {0.125, 0.08, 0.08}, {0.125, 0.115, 0.08}, {0.125, 0.125, 0.125}, {0.005, 0.005, 0.005}};
  std::vector<double> px, py, pz;
  for (const Vec3& q : x) px.push_back(q[0]), py.push_back(q[1]), pz.push_back(q[2]);
  TriangleHits hits;
  locator.query(px, py, pz, hits);
  ConvexFaces convex;
  locator.convex_faces(px, py, pz, std::span<const TriangleHits>(&hits, 1), convex);
  // One piece each beside the edge and the corner, seeded by the nearest triangle (face 0).
  CHECK(convex.pieces[0] == 0);
  CHECK(convex.pieces[1] == 1);
  CHECK(convex.pieces[2] == 1);
  CHECK(convex.pieces[3] == 0);
  CHECK(convex.face[0][1] == 0);
  CHECK(convex.end[0][1] == 2); // plane 0 and one convex face
  CHECK(convex.end[0][2] == 3); // and two
  // Beside the edge: plane 0 is x = 0.12 (s = 0.005), the other y = 0.12 (s = -0.005).
  CHECK(convex.n[0][1].isApprox(Vec3::UnitX()));
  CHECK(std::abs(convex.s[0][1] - 0.005) < 1e-15);
  CHECK(convex.n[1][1].isApprox(Vec3::UnitY()));
  CHECK(std::abs(convex.s[1][1] + 0.005) < 1e-15);
}

TEST_CASE("has_convex_edges: none in a box tank, some with a box obstacle, found again on update",
          "[convex3d]") {
  const double r_e = 0.031;
  TriangleWallSet tank;
  add_box_tank(tank, Vec3::Zero(), Vec3::Constant(0.2), false, 0);
  add_box_tank(tank, Vec3::Constant(0.3), Vec3::Constant(0.4), true, 0); // open top: no lid
  CHECK_FALSE(TriangleLocator(tank, r_e).has_convex_edges());
  TriangleWallSet box;
  add_box_obstacle(box, Vec3::Constant(0.04), Vec3::Constant(0.12), 1);
  TriangleLocator locator(box, r_e);
  CHECK(locator.has_convex_edges());
  // Mirrored through x = 0 the box's triangles turn their normals inwards: a closed tank.
  for (Vec3& x : box.nodes().x) x[0] = -x[0];
  box.update();
  locator.update();
  CHECK_FALSE(locator.has_convex_edges());
  // Without convex edges no point gets a convex face.
  const std::vector<double> px = {-0.045, -0.115}, py = {0.045, 0.08}, pz = {0.045, 0.08};
  std::array<TriangleHits, 3> faces;
  locator.query(px, py, pz, faces[0]);
  locator.corner_faces(px, py, pz, faces);
  ConvexFaces convex;
  locator.convex_faces(px, py, pz, faces, convex);
  CHECK(faces[0].triangle[0] >= 0);
  CHECK(convex.pieces[0] == 0);
  CHECK(convex.pieces[1] == 0);
}

TEST_CASE("convex_faces: at the foot of a box standing on the floor, a piece seeded by the box's "
          "face where it acts and one of its own beyond the vertical edge",
          "[convex3d]") {
  const double l0 = 0.01, r_e = 3.1 * l0;
  TriangleWallSet walls;
  add_box_tank(walls, Vec3::Zero(), Vec3::Constant(0.2), false, 0);
  // The box [0.04, 0.12] x [0, 0.08] x [0.04, 0.12] on the floor y = 0: its top and four sides.
  add_box_obstacle(walls, Vec3(0.04, 0.0, 0.04), Vec3(0.12, 0.08, 0.12), 1, 1);
  const TriangleLocator locator(walls, r_e);
  // At the foot of the face x = 0.12 near its edge with z = 0.12 (the floor nearest, the face a
  // corner face), and beyond that vertical edge (no face of the box acts).
  const std::vector<Vec3> x = {{0.125, 0.003, 0.115}, {0.125, 0.004, 0.125}};
  std::vector<double> px, py, pz;
  for (const Vec3& q : x) px.push_back(q[0]), py.push_back(q[1]), pz.push_back(q[2]);
  std::array<TriangleHits, 3> faces;
  locator.query(px, py, pz, faces[0]);
  locator.corner_faces(px, py, pz, faces);
  REQUIRE(walls.face_normal(faces[0].triangle[0]).isApprox(Vec3::UnitY()));
  REQUIRE(walls.face_normal(faces[1].triangle[0]).isApprox(Vec3::UnitX()));
  REQUIRE(walls.face_normal(faces[0].triangle[1]).isApprox(Vec3::UnitY()));
  REQUIRE(faces[1].triangle[1] < 0);
  ConvexFaces convex;
  locator.convex_faces(px, py, pz, faces, convex);
  for (std::size_t i = 0; i < 2; ++i) {
    CHECK(convex.pieces[i] == 1);
    CHECK(convex.face[0][i] == (i == 0 ? 1 : -1));
    CHECK(convex.end[0][i] == 2);
    // The piece: behind x = 0.12 and z = 0.12, either plane first.
    const Vec3 sum = convex.n[0][i] + convex.n[1][i];
    CHECK(sum.isApprox(Vec3(1.0, 0.0, 1.0)));
    for (std::size_t k = 0; k < 2; ++k)
      CHECK(std::abs(convex.s[k][i] - (x[i] - Vec3(0.12, 0.0, 0.12)).dot(convex.n[k][i])) < 1e-15);
  }
}
