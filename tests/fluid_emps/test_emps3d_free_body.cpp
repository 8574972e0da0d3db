// Momentum of fluid and walls in 3-D (#43): a block of water thrown without gravity at a free
// rigid cube of triangles, off its centre line. The cube receives minus the forces the particles
// record (eq. 52: every slot, the viscous mirror term's too) and moves and turns with them, so
// that the water's and the cube's linear momentum together stay what the water started with, to
// round-off (the fluid-fluid terms are antisymmetric in pairs).
#include "fluid_emps/emps_fluid.hpp"
#include "geometry_erp/box_walls.hpp"
#include "test_support.hpp"

#include <catch2/catch.hpp>

#include <Eigen/Geometry>

#include <algorithm>
#include <vector>

using namespace fsi;

namespace {

/// A cube of triangles moving as a rigid body: centre C, velocity V, rotation R from its
/// initial nodes X0 about C0, angular velocity w; isotropic inertia I (a cube's).
struct FreeCube {
  FreeCube(erp::TriangleWallSet& walls, const Vec3& lo, double a, double mass)
      : C0(lo + Vec3::Constant(0.5 * a)), C(C0), M(mass), I(mass * a * a / 6.0) {
    erp::add_box_obstacle(walls, lo, lo + Vec3::Constant(a), 0);
    X0 = walls.nodes().x;
    place(walls);
  }
  /// The nodes at C, R and their velocities V + w x r (the walls at t + dt before a step).
  void place(erp::TriangleWallSet& walls) const {
    auto& nodes = walls.nodes();
    for (std::size_t k = 0; k < X0.size(); ++k) {
      const Vec3 r = R * (X0[k] - C0);
      nodes.x[k] = C + r;
      nodes.v[k] = V + w.cross(r);
      nodes.a[k] = Vec3::Zero();
    }
    walls.update();
  }
  /// One explicit step of the body's motion over dt (with the velocities of the last push).
  void move(double dt) {
    C += dt * V;
    const double angle = dt * w.norm();
    if (angle > 0) R = Eigen::AngleAxisd(angle, w.normalized()).toRotationMatrix() * R;
  }
  /// The body receives -f at each recorded wall point: its momentum and angular momentum.
  void push(const emps::WallForces3& forces, const erp::TriangleWallSet& walls, double dt) {
    const auto& X = walls.nodes().x;
    Vec3 F = Vec3::Zero(), T = Vec3::Zero();
    for (const emps::TriangleForces& slot : forces)
      for (std::size_t i = 0; i < slot.triangle.size(); ++i) {
        const int t = slot.triangle[i];
        if (t < 0) continue;
        const auto& n = walls.triangles().node[static_cast<std::size_t>(t)];
        const Vec3 x_wall = slot.bary[i][0] * X[static_cast<std::size_t>(n[0])] +
                            slot.bary[i][1] * X[static_cast<std::size_t>(n[1])] +
                            slot.bary[i][2] * X[static_cast<std::size_t>(n[2])];
        F -= slot.f[i];
        T -= (x_wall - C).cross(slot.f[i]);
      }
    V += dt * F / M;
    w += dt * T / I;
  }
  std::vector<Vec3> X0;
  Vec3 C0, C, V = Vec3::Zero(), w = Vec3::Zero();
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  double M, I;
};

Vec3 momentum(const emps::Particles3& p, double m) {
  Vec3 P = Vec3::Zero();
  for (std::size_t i = 0; i < p.size(); ++i)
    P += m * Vec3(p.velocity[0][i], p.velocity[1][i], p.velocity[2][i]);
  return P;
}

} // namespace

TEST_CASE("emps 3-D: water thrown at a free rigid cube of triangles: the water's and the cube's "
          "momentum together kept to round-off",
          "[emps]") {
  const double l0 = 0.01, dt = 1e-4;
  emps::FluidOptions3 o = emps::test::water<3>(l0, -0.2, 0.4);
  emps::apply_wall_preset(o, emps::WallModel::standard); // every wall term of the shipped wall
  o.viscosity = 1e-3;
  o.wall.contact.alpha_rep = 1e5;
  const Vec3 U(1.0, 0.0, 0.0);
  // A 4 l0 block at x in [0, 4 l0], moving at U towards a 6 l0 cube 2 l0 ahead of it, offset
  // by 2 l0 in y and z so that the water strikes an edge and a corner and the cube turns.
  std::vector<Vec3> x = emps::test::block(4, 4, 4, l0);
  erp::TriangleWallSet walls;
  const double m = o.density * o.volume(), M_f = m * static_cast<double>(x.size());
  FreeCube cube(walls, Vec3(6 * l0, 2 * l0, 2 * l0), 6 * l0, 2.0 * M_f);
  emps::EmpsFluid3 fluid(o, x, walls);
  fluid.set_velocities(std::vector<Vec3>(x.size(), U));
  const Vec3 P0 = M_f * U;
  double drift = 0.0;
  const long steps = 600;
  for (long s = 0; s < steps; ++s) {
    cube.move(dt);
    cube.place(walls); // the walls at t + dt, then the step
    fluid.advance(static_cast<double>(s) * dt, dt);
    cube.push(fluid.triangle_forces(), walls, dt);
    const Vec3 P = momentum(fluid.particles(), m) + cube.M * cube.V;
    drift = std::max(drift, (P - P0).norm() / P0.norm());
  }
  WARN("water (" << x.size() << " particles) thrown at a free cube, " << steps
                 << " steps: largest |P_water + P_cube - P0| / |P0| " << drift
                 << "; the cube's momentum / P0 " << (cube.M * cube.V / P0.norm()).transpose()
                 << ", its angular velocity " << cube.w.transpose() << " rad/s");
  CHECK(fluid.removed() == 0);
  CHECK(drift <= 1e-12);
  CHECK(cube.M * cube.V.x() >= 0.1 * P0.norm()); // the water has pushed the cube along U
  CHECK(cube.w.norm() > 0.0);                    // and, off its centre line, turned it
}
