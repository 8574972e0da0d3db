// The solid's wedge beside a 3-D box obstacle's convex edges and corners (#43): on a lattice at
// rest around a closed box of triangles standing free in a tank, pnd (eq. 20's z) against the
// particle-wall reference (the lattice filling the box counted directly) and the wall pressure
// term under a uniform pressure (eqs. 25-26) against zero, with and without convex_corners.
#include "fluid_emps/space_wall_terms.hpp"
#include "test_support.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

using namespace fsi;

namespace {

/// Per particle within r_e of the box (and beyond r_e of the tank): the number of its convex
/// faces (0 a face, 1 an edge, 2 a corner; its one convex piece's), pnd minus the reference, eq.
/// 10's sum at uniform pressure P (fluid plus wall terms; zero for the full lattice), the wall term
/// and face 0's n_wall, and the half-space's term there, -(3/n0) 2 P wall_gradient_sum(r) n_wall,
/// where its nearest point lies inside a face (not on an edge or vertex; else -inf).
struct ConvexSample {
  int convex;
  double pnd_error;
  Vec3 gradient, mirror, n_face;
  double half_space;
};

using ConvexScene = emps::test::LatticeScene<ConvexSample>;

/// An 18 l0 cube tank holding a 4 l0 box at [7 l0, 11 l0]^3 (narrower than 2 r_e: every particle
/// within r_e of it has convex faces, opposite ones included), the lattice l0/2 + k l0 outside
/// the box at rest under a uniform pressure P.
ConvexScene box_in_tank(bool convex_corners) {
  ConvexScene s;
  const double l0 = s.l0;
  const Vec3 lo = Vec3::Constant(7 * l0), hi = Vec3::Constant(11 * l0);
  emps::test::CubeTank tank(l0, convex_corners);
  const emps::FluidOptions3& o = tank.o;
  const double L = tank.L, r_e = tank.r_e;
  const particles::MpsWeight& w = tank.w;
  s.n0 = tank.n0;
  erp::add_box_obstacle(tank.walls, lo, hi, 1);
  const auto inside = [&](const Vec3& x) {
    return (x.array() > lo.array()).all() && (x.array() < hi.array()).all();
  };
  std::vector<Vec3> x, solid; // the fluid lattice and the reference's wall particles
  for (const Vec3& q : emps::test::block(18, 18, 18, l0)) (inside(q) ? solid : x).push_back(q);
  const erp::TriangleLocator locator(tank.walls, r_e);
  const emps::test::AtRest rest(o, x, s.P, locator);
  const emps::SpaceWallTerms terms = rest.terms(o, s.n0);
  const emps::SpaceHits& hits = rest.hits;
  const erp::ConvexFaces& convex = rest.convex;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const Vec3 gap = (lo - x[i]).cwiseMax(x[i] - hi).cwiseMax(0.0);
    if (gap.norm() >= r_e || emps::test::walls_near(x[i], L, r_e) > 0) continue;
    const emps::test::DirectSums direct = emps::test::direct_sums(x, i, r_e, w, s.P);
    const double fluid_pnd = direct.pnd;
    const Vec3 fluid = direct.gradient;
    double solid_pnd = 0.0;
    for (const Vec3& q : solid) solid_pnd += w((q - x[i]).norm());
    Vec3 mirror = Vec3::Zero(); // the wall term (one face, no contact at rest)
    emps::WallShares3 shares;
    terms.add_pressure(i, 0.0005, mirror, shares);
    const double half_space =
        hits[0].feature[i] == TriangleFeature::face
            ? -3.0 / s.n0 * 2.0 * s.P * erp::wall_gradient_sum<3>(hits[0].r[i], l0, r_e, w)
            : -std::numeric_limits<double>::infinity();
    const int faces = convex.pieces[i] == 0 ? 0 : convex.end[0][i] - 1;
    s.samples.push_back({faces, terms.pnd(i, fluid_pnd) - (fluid_pnd + solid_pnd),
                         3.0 / s.n0 * fluid + mirror, mirror, hits[0].n_wall[i], half_space});
  }
  return s;
}

} // namespace

TEST_CASE("emps 3-D walls: beside a box obstacle's convex edges and corners pnd at rest equals "
          "the lattice filling the box counted directly, and the wall pressure term balances a "
          "uniform pressure, only with convex_corners",
          "[emps][walls3d][convex]") {
  const ConvexScene with = box_in_tank(true), without = box_in_tank(false);
  REQUIRE(with.samples.size() == without.samples.size());
  std::array<double, 3> pnd_with{}, pnd_without{}, grad_with{}, grad_without{};
  std::array<int, 3> count{};
  for (std::size_t k = 0; k < with.samples.size(); ++k) {
    const ConvexSample &a = with.samples[k], &b = without.samples[k];
    const auto c = static_cast<std::size_t>(std::min(a.convex, 2));
    ++count[c];
    pnd_with[c] = std::max(pnd_with[c], std::abs(a.pnd_error) / with.n0);
    pnd_without[c] = std::max(pnd_without[c], std::abs(b.pnd_error) / with.n0);
    grad_with[c] = std::max(grad_with[c], a.gradient.norm() * with.l0 / with.P);
    grad_without[c] = std::max(grad_without[c], b.gradient.norm() * with.l0 / with.P);
  }
  INFO("particles with 0, 1, 2 or more convex faces: " << count[0] << ", " << count[1] << ", "
                                                       << count[2]);
  INFO("worst |pnd - reference| / n0 with convex_corners: "
       << pnd_with[0] << ", " << pnd_with[1] << ", " << pnd_with[2]
       << "; without: " << pnd_without[0] << ", " << pnd_without[1] << ", " << pnd_without[2]);
  INFO("worst |<grad p>_i| l0 / P with convex_corners: "
       << grad_with[0] << ", " << grad_with[1] << ", " << grad_with[2]
       << "; without: " << grad_without[0] << ", " << grad_without[1] << ", " << grad_without[2]);
  CHECK(count[1] > 0);
  CHECK(count[2] > 0);
  for (std::size_t c = 0; c < 3; ++c) {
    CHECK(pnd_with[c] < 1e-12);
    CHECK(grad_with[c] < 1e-12);
  }
  // Without: the lattice beyond the edges' and corners' other faces counted as solid.
  CHECK(std::max(pnd_without[1], pnd_without[2]) > 0.15);
  CHECK(std::max(grad_without[1], grad_without[2]) > 0.2);
}

TEST_CASE("emps 3-D walls: the convex wedge takes solid away from pnd and weakens face 0's push "
          "without turning it",
          "[emps][walls3d][convex]") {
  const ConvexScene with = box_in_tank(true), without = box_in_tank(false);
  int corrected = 0, pushed = 0;
  for (std::size_t k = 0; k < with.samples.size(); ++k) {
    const ConvexSample &a = with.samples[k], &b = without.samples[k];
    // pnd: the wedge is a part of the half-space, never more.
    CHECK(a.pnd_error <= b.pnd_error + 1e-12 * with.n0);
    if (a.convex == 0) continue;
    corrected += a.pnd_error < b.pnd_error - 1e-6 * with.n0;
    // The wall term under p > 0 pushes along face 0's normal (zero where the wedge's lattice is
    // out of reach); beside a face less than the whole half-space's would.
    CHECK(a.mirror.dot(a.n_face) <= 0.0);
    pushed += a.mirror.dot(a.n_face) < 0.0;
    CHECK(a.mirror.dot(a.n_face) >= a.half_space - 1e-12 * with.P / with.l0);
  }
  CHECK(corrected > 0);
  CHECK(pushed > 0);
}

TEST_CASE("emps 3-D walls: between two boxes each convex piece's share is its own lattice sum, "
          "recorded on its own box",
          "[emps][walls3d][convex]") {
  // Two 4 l0 boxes 2 l0 apart along x in the 18 l0 tank, the lattice outside them at rest under
  // P: between them a particle's nearest face and the facing one (a corner face) both seed a
  // piece, of two solids, so the pieces are disjoint (their intersection empty) and each share
  // (ConvexPart::share) is that piece's region_lattice_sum3 alone (no other acting face: no
  // images).
  const double l0 = 0.01, P = 1000.0 * 9.81 * 0.18;
  emps::test::CubeTank tank(l0, true);
  const std::array<Vec3, 2> lo{l0 * Vec3(4, 7, 7), l0 * Vec3(10, 7, 7)};
  const std::array<Vec3, 2> hi{l0 * Vec3(8, 11, 11), l0 * Vec3(14, 11, 11)};
  const erp::TriangleRange a = erp::add_box_obstacle(tank.walls, lo[0], hi[0], 1);
  erp::add_box_obstacle(tank.walls, lo[1], hi[1], 2);
  const auto box_of = [&](int t) { return t < a.first_triangle + a.triangle_count ? 0 : 1; };
  std::vector<Vec3> x;
  for (const Vec3& q : emps::test::block(18, 18, 18, l0)) {
    bool inside = false;
    for (std::size_t b = 0; b < 2; ++b)
      inside = inside || ((q.array() > lo[b].array()).all() && (q.array() < hi[b].array()).all());
    if (!inside) x.push_back(q);
  }
  const erp::TriangleLocator locator(tank.walls, tank.r_e);
  const emps::test::AtRest rest(tank.o, x, P, locator);
  const emps::SpaceWallTerms terms = rest.terms(tank.o, tank.n0);
  const erp::ConvexFaces& convex = rest.convex;
  emps::WallForces3 forces;
  for (std::size_t k = 0; k < emps::pressure_slots3; ++k)
    forces[k].resize(x.size()); // viscous: empty
  int between = 0, into_own_box = 0;
  double worst = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    Vec3 grad = Vec3::Zero();
    emps::WallShares3 shares;
    terms.add_pressure(i, 5e-4, grad, shares);
    terms.record_forces(i, shares, tank.o.volume(), forces);
    if (convex.pieces[i] != 2 || rest.hits[2].triangle[i] >= 0 || convex.face[0][i] < 0 ||
        convex.face[1][i] < 0 || box_of(convex.seed[0][i]) == box_of(convex.seed[1][i]))
      continue;
    ++between;
    const emps::SpaceWallTerms::ConvexPart part = terms.convex_part(i);
    for (std::size_t q = 0; q < 2; ++q) {
      std::vector<erp::HalfSpace3> piece;
      for (std::size_t k = convex.begin(q, i); k < convex.end[q][i]; ++k)
        piece.push_back({convex.n[k][i], convex.s[k][i]});
      const auto own = erp::region_lattice_sum3(piece, l0, tank.r_e, tank.w);
      REQUIRE(own);
      worst = std::max(worst, (part.share[q] - own->gradient).norm() / own->gradient.norm());
      const int b = box_of(forces[emps::max_faces3 + q].triangle[i]);
      const Vec3 load = -forces[emps::max_faces3 + q].f[i];
      into_own_box += load.dot(0.5 * (lo[b] + hi[b]) - x[i]) > 0.0;
    }
  }
  INFO(between << " particles with a piece of each box; worst |share - own sum| / |own sum| "
               << worst << ", loads into their own box " << into_own_box);
  CHECK(between > 0);
  CHECK(worst <= 1e-12);
  CHECK(into_own_box == 2 * between);
}
