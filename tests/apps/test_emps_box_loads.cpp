// A box obstacle as a structure's interface in still water (issues 43, 46): the convex pieces'
// force on the right triangle (eq. 52). A T10 box standing on the floor of the 18 l0 cube tank
// (its five wetted faces as erp::InterfaceTriangles, no bottom), the lattice outside it at rest
// under the hydrostatic pressure: each particle's wall term split by SpaceWallTerms::add_pressure
// into its faces' and its convex pieces' shares and recorded by record_forces, the box's loads
// projected onto its interface nodes (emps_plugin::project_triangle_forces, eqs. 53-59).
#include "emps/triangle_loads.hpp"
#include "geometry_erp/interface_triangles.hpp"
#include "structure_fem/box_mesher.hpp"
#include "structure_fem/interface_mesh.hpp"
#include "test_support.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <vector>

using namespace fsi;

namespace {

/// The box [7 l0, 11 l0] x [0, 4 l0] x [7 l0, 11 l0] on the floor y = 0 of CubeTank (group 0),
/// a T10 block of 2 x 2 x 2 cells wetted on all sides but its bottom (group 1), and the lattice
/// l0/2 + k l0 outside it at rest under p = rho g (L - y).
struct BoxOnFloor {
  emps::test::CubeTank tank{0.01, true};
  double l0 = tank.o.l0;
  Vec3 lo = l0 * Vec3(7, 0, 7), hi = l0 * Vec3(11, 4, 11);
  fem::FeInterface3 fe = fem::interface_of(fem::make_box_mesh({lo, hi - lo, {2, 2, 2}}),
                                           {"x_min", "x_max", "y_max", "z_min", "z_max"});
  erp::InterfaceTriangles box{tank.walls, fe.mesh, 1};
  std::vector<Vec3> x = fluid_lattice();
  std::optional<erp::TriangleLocator> locator;
  std::optional<emps::test::AtRest> rest;

  BoxOnFloor() {
    tank.walls.update();
    locator.emplace(tank.walls, tank.r_e);
    rest.emplace(tank.o, x, 0.0, *locator);
    for (std::size_t i = 0; i < x.size(); ++i)
      rest->p.p[i] = tank.o.density * 9.81 * (tank.L - x[i][1]);
  }
  std::vector<Vec3> fluid_lattice() const {
    std::vector<Vec3> out;
    for (const Vec3& q : emps::test::block(18, 18, 18, l0))
      if (!((q.array() > lo.array()).all() && (q.array() < hi.array()).all())) out.push_back(q);
    return out;
  }
  bool on_box(int t) const {
    return t >= box.first_triangle() && t < box.first_triangle() + box.triangle_count();
  }
};

} // namespace

TEST_CASE("emps 3-D wall forces: a box obstacle as an interface in still water takes its convex "
          "pieces' force, pointing into it, and the tank's floor none of it",
          "[apps][emps][3d][convex]") {
  const BoxOnFloor s;
  const emps::FluidOptions3& o = s.tank.o;
  const emps::SpaceWallTerms terms = s.rest->terms(o, s.tank.n0);
  const emps::SpaceHits& hits = s.rest->hits;
  const erp::ConvexFaces& convex = s.rest->convex;
  const double V = o.volume(), dt = 5e-4;
  const std::size_t n = s.x.size();
  emps::WallForces3 forces;
  for (std::size_t k = 0; k < emps::pressure_slots3; ++k) forces[k].resize(n); // viscous: empty
  // The box's and the tank's wall terms (V times) particle by particle: each acting face's mirror
  // (unless it seeds a piece), contact and share of the images behind several walls on its own
  // triangle's wall, every convex piece on the box (the tank has no convex edge); each against
  // the particle's loads recorded there (worst difference of any particle), and summed.
  Vec3 box_terms = Vec3::Zero();
  int with_pieces = 0, several = 0, own_seeded = 0, seeds_off_box = 0, foot = 0;
  double foot_vertical = 0.0, foot_min_inward = 1.0, scale = 0.0, box_worst = 0.0;
  double tank_worst = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    Vec3 grad = Vec3::Zero();
    emps::WallShares3 shares;
    terms.add_pressure(i, dt, grad, shares);
    terms.record_forces(i, shares, V, forces);
    scale = std::max(scale, V * grad.norm());
    const emps::SpaceWallTerms::ConvexPart part = terms.convex_part(i);
    const Vec3 corner = terms.corner_mirror_pressure(i, part.replaced);
    const std::array<Vec3, emps::max_faces3> split = emps::split_corner_term(corner, hits, i);
    Vec3 on_box = V * terms.convex_pressure(i, part), on_tank = Vec3::Zero();
    for (std::size_t k = 0; k < emps::max_faces3; ++k) {
      const int t = hits[k].triangle[i];
      if (t < 0) continue;
      const Vec3 mirror = part.replaced >> k & 1u ? Vec3::Zero() : terms.mirror_pressure(i, k);
      (s.on_box(t) ? on_box : on_tank) += V * (split[k] + mirror + terms.contact(i, k, dt));
    }
    box_terms += on_box;
    for (const emps::TriangleForces& slot : forces) // the loads, -f, slot by slot (filled ones)
      if (i < slot.triangle.size() && slot.triangle[i] >= 0)
        (s.on_box(slot.triangle[i]) ? on_box : on_tank) += slot.f[i];
    box_worst = std::max(box_worst, on_box.norm());
    tank_worst = std::max(tank_worst, on_tank.norm());
    const std::size_t pieces = convex.pieces[i];
    with_pieces += pieces > 0;
    several += pieces > 1; // where overlapping pieces would share
    for (std::size_t q = 0; q < pieces; ++q) {
      seeds_off_box += !s.on_box(convex.seed[q][i]);
      own_seeded += convex.face[q][i] < 0;
    }
    // Beyond the foot of a vertical edge the floor is the only acting face and the box seeds a
    // piece of its own: its load (-f on the seed) lies along the floor (the piece's lattice and
    // its image below the floor are symmetric about the particle's row) and into the box.
    if (pieces == 1 && convex.face[0][i] < 0 && !s.on_box(hits[0].triangle[i]) &&
        hits[1].triangle[i] < 0) {
      const Vec3 load = -forces[emps::max_faces3].f[i];
      if (load.norm() == 0.0) continue;
      ++foot;
      const Vec3 to_box = s.x[i].cwiseMax(s.lo).cwiseMin(s.hi) - s.x[i];
      foot_vertical = std::max(foot_vertical, std::abs(load[1]) / load.norm());
      foot_min_inward = std::min(foot_min_inward, load.normalized().dot(to_box.normalized()));
    }
  }
  // The structure's loads (eqs. 53-59) and each wetted face's resultant.
  coupling::InterfaceLoads3 loads;
  app::emps_plugin::project_triangle_forces(forces, s.box, loads);
  Vec3 nodal = Vec3::Zero();
  for (const Vec3& f : loads.f) nodal += f;
  std::vector<Vec3> face(s.fe.mesh.faces.size(), Vec3::Zero());
  for (const emps::TriangleForces& slot : forces)
    for (std::size_t i = 0; i < slot.triangle.size(); ++i)
      if (s.on_box(slot.triangle[i]))
        face[static_cast<std::size_t>(s.box.face(slot.triangle[i]))] -= slot.f[i];
  Vec3 faces_sum = Vec3::Zero();
  int inward = 0;
  const Vec3 centre = 0.5 * (s.lo + s.hi);
  for (std::size_t F = 0; F < face.size(); ++F) {
    faces_sum += face[F];
    Vec3 c = Vec3::Zero();
    for (std::size_t j = 0; j < 3; ++j) c += s.fe.mesh.X0[s.fe.mesh.faces[F][j]] / 3.0;
    inward += face[F].dot(centre - c) > 0.0;
  }
  WARN("box on the floor as an interface, "
       << n << " particles: " << with_pieces << " with convex pieces (" << several
       << " with two or more), " << own_seeded
       << " pieces seeded by no acting face; total on the box " << box_terms.transpose()
       << " N, nodal loads' sum - terms " << (nodal - box_terms).norm() << " N, faces' sum - terms "
       << (faces_sum - box_terms).norm() << " N; worst particle's loads - terms on the box "
       << box_worst << " N, on the tank " << tank_worst << " N (scale " << scale << " N); "
       << inward << " of " << face.size() << " faces loaded inward; " << foot
       << " particles beyond the feet of the vertical edges: largest |vertical| / |load| "
       << foot_vertical << ", smallest cosine to the box " << foot_min_inward);
  CHECK(own_seeded > 0); // the convex edges and corners act, at the foot too
  CHECK((nodal - box_terms).norm() <= 1e-12 * scale);
  CHECK((faces_sum - box_terms).norm() <= 1e-12 * scale);
  CHECK(seeds_off_box == 0);
  CHECK(box_worst <= 1e-12 * scale);
  CHECK(tank_worst <= 1e-12 * scale); // none of the pieces' term on the tank's floor
  CHECK(inward == static_cast<int>(face.size()));
  CHECK(foot > 0);
  CHECK(foot_vertical <= 1e-12);
  CHECK(foot_min_inward > 0.0);
}
