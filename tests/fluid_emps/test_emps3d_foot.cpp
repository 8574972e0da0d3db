// The foot of a box standing on the floor (#43): the floor is a concave neighbour of the box's
// faces, and beyond a vertical edge no face of the box acts at all; on a lattice at rest pnd
// (eq. 20's z) against the particle-wall reference (the lattice of the floor and of the box counted
// directly) and the wall pressure term under a uniform pressure (eqs. 25-26) against zero.
#include "fluid_emps/space_wall_terms.hpp"
#include "test_support.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace fsi;

namespace {

/// Where a particle within r_e of the box lies: beside a face (inside the footprint's range along
/// x or z) or beyond a vertical edge, near the floor (its foot) or above it.
enum Zone { face_foot, edge_foot, face_above, edge_above, zones };

struct FootSample {
  Zone zone;
  int pieces;       ///< convex pieces (TriangleLocator::convex_faces)
  bool seeded;      ///< one of them seeded by no acting face
  double pnd_error; ///< pnd minus the reference
  Vec3 gradient;    ///< eq. 10 at uniform P: the fluid's sum plus the wall terms
  Vec3 faces_sum;   ///< the wall term's shares on the faces and pieces (eq. 52) summed
  Vec3 wall;        ///< the wall term
  Vec3 convex;      ///< the pieces' term
  Vec3 to_box;      ///< from the particle to the box's nearest point
  double pnd;
};

using FootScene = emps::test::LatticeScene<FootSample>;

/// A 4 l0 box [7 l0, 11 l0] x [0, 4 l0] x [7 l0, 11 l0] standing on the floor y = 0 of an 18 l0
/// cube tank: its top and four sides, normals out of it, no bottom (as scripts/tank_with_box_stl
/// writes it). The lattice l0/2 + k l0 outside the box at rest under a uniform pressure P.
FootScene box_on_floor(bool convex_corners) {
  FootScene s;
  const double l0 = s.l0;
  const Vec3 lo(7 * l0, 0.0, 7 * l0), hi(11 * l0, 4 * l0, 11 * l0);
  emps::test::CubeTank tank(l0, convex_corners);
  const emps::FluidOptions3& o = tank.o;
  const double L = tank.L, r_e = tank.r_e;
  const particles::MpsWeight& w = tank.w;
  s.n0 = tank.n0;
  erp::add_box_obstacle(tank.walls, lo, hi, 1, 1); // no bottom: open at y = lo.y
  const auto in_box = [&](const Vec3& x) {
    return (x.array() > lo.array()).all() && (x.array() < hi.array()).all();
  };
  const auto in_tank = [&](const Vec3& x) {
    return (x.array() > 0.0).all() && (x.array() < L).all();
  };
  std::vector<Vec3> x, solid; // the fluid lattice and the reference's wall particles
  for (int k = -4; k < 22; ++k)
    for (int j = -4; j < 22; ++j)
      for (int i = -4; i < 22; ++i) {
        const Vec3 q = l0 * Vec3(i + 0.5, j + 0.5, k + 0.5);
        (in_tank(q) && !in_box(q) ? x : solid).push_back(q);
      }
  const erp::TriangleLocator locator(tank.walls, r_e);
  const emps::test::AtRest rest(o, x, s.P, locator);
  const emps::SpaceWallTerms terms = rest.terms(o, s.n0);
  const emps::SpaceHits& hits = rest.hits;
  const erp::ConvexFaces& convex = rest.convex;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const Vec3 nearest = x[i].cwiseMax(lo).cwiseMin(hi);
    const Vec3 gap = (lo - x[i]).cwiseMax(x[i] - hi).cwiseMax(0.0);
    Vec3 side = x[i];
    side[1] = 0.5 * L; // the floor and the lid left out: the side walls only
    if (gap.norm() >= r_e || emps::test::walls_near(side, L, r_e) > 0 || L - x[i][1] < r_e)
      continue;
    const bool foot = x[i][1]<r_e, beyond_edge = gap[0]> 0.0 && gap[2] > 0.0;
    const Zone zone =
        foot ? (beyond_edge ? edge_foot : face_foot) : (beyond_edge ? edge_above : face_above);
    const emps::test::DirectSums direct = emps::test::direct_sums(x, i, r_e, w, s.P);
    const double fluid_pnd = direct.pnd;
    const Vec3 fluid = direct.gradient;
    double solid_pnd = 0.0;
    for (const Vec3& q : solid) solid_pnd += w((q - x[i]).norm());
    Vec3 wall = Vec3::Zero();
    emps::WallShares3 shares;
    terms.add_pressure(i, 0.0005, wall, shares);
    const emps::SpaceWallTerms::ConvexPart part = terms.convex_part(i);
    bool seeded = false;
    for (std::size_t q = 0; q < convex.pieces[i]; ++q) seeded = seeded || convex.face[q][i] < 0;
    Vec3 faces_sum = Vec3::Zero();
    for (std::size_t k = 0; k < emps::max_faces3; ++k)
      if (hits[k].triangle[i] >= 0) faces_sum += shares[k];
    for (std::size_t q = 0; q < convex.pieces[i]; ++q) faces_sum += shares[emps::max_faces3 + q];
    s.samples.push_back({zone, convex.pieces[i], seeded,
                         terms.pnd(i, fluid_pnd) - (fluid_pnd + solid_pnd),
                         3.0 / s.n0 * fluid + wall, faces_sum, wall, terms.convex_pressure(i, part),
                         nearest - x[i], terms.pnd(i, fluid_pnd)});
  }
  return s;
}

const char* zone_name(int z) {
  static const char* names[] = {"beside a face, at the foot", "beyond a vertical edge, at the foot",
                                "beside a face, above the foot", "beyond an edge, above the foot"};
  return names[z];
}

} // namespace

TEST_CASE("emps 3-D walls: at the foot of a box standing on the floor pnd at rest equals the "
          "lattice of floor and box counted directly, and the wall pressure term balances a "
          "uniform pressure, with convex_corners",
          "[emps][walls3d][convex][foot]") {
  const FootScene with = box_on_floor(true), without = box_on_floor(false);
  REQUIRE(with.samples.size() == without.samples.size());
  std::array<double, zones> pnd_with{}, pnd_without{}, grad_with{}, grad_without{};
  std::array<int, zones> count{}, seeded{};
  double split = 0.0;
  for (std::size_t k = 0; k < with.samples.size(); ++k) {
    const FootSample &a = with.samples[k], &b = without.samples[k];
    const auto z = static_cast<std::size_t>(a.zone);
    ++count[z];
    seeded[z] += a.seeded;
    pnd_with[z] = std::max(pnd_with[z], std::abs(a.pnd_error) / with.n0);
    pnd_without[z] = std::max(pnd_without[z], std::abs(b.pnd_error) / with.n0);
    grad_with[z] = std::max(grad_with[z], a.gradient.norm() * with.l0 / with.P);
    grad_without[z] = std::max(grad_without[z], b.gradient.norm() * with.l0 / with.P);
    split = std::max(split, (a.faces_sum - a.wall).norm() * with.l0 / with.P);
  }
  for (std::size_t z = 0; z < zones; ++z) {
    INFO(zone_name(static_cast<int>(z))
         << ": " << count[z] << " particles (" << seeded[z]
         << " with a piece of their own); worst |pnd - reference| / n0 " << pnd_with[z]
         << " (without convex_corners " << pnd_without[z] << "), |<grad p>_i| l0 / P "
         << grad_with[z] << " (without " << grad_without[z] << ")");
    CHECK(count[z] > 0);
    CHECK(pnd_with[z] < 1e-12);
    CHECK(grad_with[z] < 1e-12);
  }
  INFO("the faces' and pieces' shares against the wall term: " << split);
  CHECK(split < 1e-12);
  CHECK(seeded[edge_foot] > 0); // no face of the box acts there (the floor nearest)
  // Without: the box missing beyond its vertical edges' feet, the half-spaces beside them.
  CHECK(pnd_without[edge_foot] > 0.05);
  CHECK(grad_without[edge_foot] > 0.1);
}

TEST_CASE("emps 3-D walls: beyond the foot of a box's vertical edge the box's own piece raises pnd "
          "and pushes the particle away from the box",
          "[emps][walls3d][convex][foot]") {
  const FootScene with = box_on_floor(true), without = box_on_floor(false);
  int raised = 0, pushed = 0, own = 0;
  for (std::size_t k = 0; k < with.samples.size(); ++k) {
    const FootSample &a = with.samples[k], &b = without.samples[k];
    if (!a.seeded) continue;
    ++own;
    // Without it the floor's half-space alone: the box's lattice adds to pnd, never takes away.
    CHECK(a.pnd >= b.pnd - 1e-12 * with.n0);
    raised += a.pnd > b.pnd + 1e-6 * with.n0;
    // Under p > 0 the piece's term points into the box: -grad p / rho pushes the particle out.
    CHECK(a.convex.dot(a.to_box) >= 0.0);
    pushed += a.convex.dot(a.to_box) > 0.0;
  }
  INFO(own << " particles with a piece of their own: pnd raised for " << raised
           << ", pushed out for " << pushed);
  CHECK(own > 0);
  CHECK(raised > 0);
  CHECK(pushed > 0);
}
