#pragma once
// What the 2-D and 3-D fluid tests share: water at rest in a domain box, and the momentum check
// of the fluid-fluid terms, which are antisymmetric in pairs (eqs. 10, 11, the closing-pair
// viscosity), so that without gravity and walls sum_i v_i changes by round-off only.
#include "fluid_emps/emps_fluid.hpp"
#include "fluid_emps/space_wall_terms.hpp"
#include "geometry_erp/box_walls.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace fsi::emps::test {

/// Water at l0 with c = 20 m/s in the domain box [lo, hi]^D.
template <int D> BasicFluidOptions<D> water(double l0, double lo, double hi) {
  BasicFluidOptions<D> o;
  o.density = 1000.0;
  o.l0 = l0;
  o.sound_speed = 20.0;
  o.domain_min = VecD<D>::Constant(lo);
  o.domain_max = VecD<D>::Constant(hi);
  return o;
}

/// The lattice at l0/2 + k l0 filling [0, nx l0] x [0, ny l0] x [0, nz l0].
inline std::vector<Vec3> block(int nx, int ny, int nz, double l0) {
  std::vector<Vec3> x;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) x.push_back(l0 * Vec3(i + 0.5, j + 0.5, k + 0.5));
  return x;
}

/// How many of the box [0, L]^3's walls lie within r_e of x.
inline int walls_near(const Vec3& x, double L, double r_e) {
  int n = 0;
  for (int a = 0; a < 3; ++a) n += (x[a] < r_e) + (L - x[a] < r_e);
  return n;
}

/// The faces acting on every particle of p at rest (3-D): the nearest triangle, the concave
/// corners' faces and the convex ones, as the fluid's step queries them.
inline void query_faces(const erp::TriangleLocator& locator, const Particles3& p, SpaceHits& hits,
                        erp::ConvexFaces& convex) {
  locator.query(p.position[0], p.position[1], p.position[2], hits[0]);
  locator.corner_faces(p.position[0], p.position[1], p.position[2], hits);
  locator.convex_faces(p.position[0], p.position[1], p.position[2], hits, convex);
}

/// Lattice points x at rest under a uniform pressure P, binned, with the faces and convex pieces
/// the step would query: what the 3-D wall terms are tested on (terms(), which refers to them).
struct AtRest {
  Particles3 p;
  particles::BasicCellGrid<3> grid;
  SpaceHits hits;
  erp::ConvexFaces convex;
  AtRest(const FluidOptions3& o, const std::vector<Vec3>& x, double P,
         const erp::TriangleLocator& locator)
      : grid(o.domain_min, o.domain_max, 1.1 * o.r_e()) {
    p.resize(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) {
      for (int a = 0; a < 3; ++a) p.position[a][i] = x[i][a];
      p.p[i] = P;
    }
    grid.bin(p.position.coords(), p.size());
    query_faces(locator, p, hits, convex);
  }
  SpaceWallTerms terms(const FluidOptions3& o, double n0) const {
    return SpaceWallTerms(o, n0, p, grid, hits, convex);
  }
};

/// A lattice at rest under a uniform pressure P (the 3-D wall tests') and what a test samples on
/// it.
template <class Sample> struct LatticeScene {
  double l0 = 0.01, P = 1000.0 * 9.81 * 0.18, n0 = 0.0;
  std::vector<Sample> samples;
};

/// The setting of the box tests on it (test_emps3d_convex.cpp, test_emps3d_foot.cpp): water at
/// l0 with convex_corners as given in the 18 l0 cube tank [0, L]^3 (walls, group 0), and the
/// lattice's n0 (eq. 9); the test adds its box to the walls.
struct CubeTank {
  FluidOptions3 o;
  double L, r_e;
  particles::MpsWeight w;
  double n0;
  erp::TriangleWallSet walls;
  CubeTank(double l0, bool convex_corners)
      : o(water<3>(l0, -0.05, 0.25)), L(18 * l0), r_e(o.r_e()), w(r_e),
        n0(erp::lattice_n0<3>(l0, r_e, w)) {
    o.wall.convex_corners = convex_corners;
    erp::add_box_tank(walls, Vec3::Zero(), Vec3::Constant(L), false, 0);
  }
};

/// Eq. 9's sum over the points of x within r_e of x[i] (i left out) and eq. 10's geometric sum
/// at a uniform pressure P, 2 P sum (x_j - x_i) w / r^2.
struct DirectSums {
  double pnd = 0.0;
  Vec3 gradient = Vec3::Zero();
};
inline DirectSums direct_sums(const std::vector<Vec3>& x, std::size_t i, double r_e,
                              const particles::MpsWeight& w, double P) {
  DirectSums s;
  for (std::size_t j = 0; j < x.size(); ++j) {
    const Vec3 d = x[j] - x[i];
    const double r2 = d.squaredNorm();
    if (j == i || r2 >= r_e * r_e) continue;
    s.pnd += w(std::sqrt(r2));
    s.gradient += 2.0 * P * w.inside(std::sqrt(r2)) / r2 * d;
  }
  return s;
}

template <int D> VecD<D> momentum(const BasicParticles<D>& p) {
  VecD<D> m = VecD<D>::Zero();
  for (std::size_t i = 0; i < p.size(); ++i)
    for (int a = 0; a < D; ++a) m[a] += p.velocity[a][i];
  return m;
}

struct MomentumDrift {
  double worst = 0.0;   ///< largest |change of sum_i v_i| of a step / sum_i |v_i(0)|
  long pressurised = 0; ///< particle-steps with p > 0 (the pressure gradient took part)
};

/// Sets the initial velocities v and advances `steps` steps of dt from t = 0.
template <int D>
MomentumDrift momentum_drift(BasicEmpsFluid<D>& fluid, const std::vector<VecD<D>>& v, int steps,
                             double dt) {
  double scale = 0.0;
  for (const VecD<D>& vi : v) scale += vi.norm();
  fluid.set_velocities(v);
  MomentumDrift out;
  VecD<D> before = momentum(fluid.particles());
  for (int k = 0; k < steps; ++k) {
    fluid.advance(k * dt, dt);
    const VecD<D> after = momentum(fluid.particles());
    out.worst = std::max(out.worst, (after - before).norm() / scale);
    before = after;
    for (double pi : fluid.particles().p) out.pressurised += pi > 0.0;
  }
  return out;
}

} // namespace fsi::emps::test
