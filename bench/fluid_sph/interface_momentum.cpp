// Momentum exchange across a moving interface (issue 18: "action = -reaction ... the reference
// code does not quite conserve it; measure both"). The case of the plug-in test "fluid thrown at a
// free rigid body" (tests/apps/test_sph_plugin.cpp): no gravity, a 0.04 m square of water at
// 1 m/s, dp = 0.005 m (or argv[1]), c0 = 20 m/s, nu = 1e-6, rkgc (argv[2] = none: B = I, where
// the two forms coincide), alpha = 0.3, hits a free
// 0.04 x 0.06 m body (1000 kg/m^3) 0.02 m away; the body's boundary points (4 layers) follow its
// translation, M dV/dt = sum of the points' forces, exchanged every acoustic step, to 0.04 s.
// Both reactions of SphFluid::Reaction: exact (what the fluid gains from the points, reversed)
// and reference_code (the dummy pressure of eq. 16 without B_i). Prints, per form, the body's
// impulse J = M V and the drift of the total momentum |P_fluid + M V - P0| at the end and its
// largest value, each per unit impulse |J|.
#include "fluid_sph/interface_boundary.hpp"
#include "fluid_sph/sph_fluid.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

using namespace fsi;

namespace {

// The body's outline as an order-1 interface mesh, edges of `length`, solid on the left.
InterfaceMesh outline(const std::vector<Vec2>& corners, double length) {
  InterfaceMesh mesh;
  mesh.order = 1;
  for (std::size_t s = 0; s < corners.size(); ++s) {
    const Vec2 a = corners[s], b = corners[(s + 1) % corners.size()];
    const int n = static_cast<int>(std::ceil((b - a).norm() / length - 1e-9));
    for (int k = 0; k < n; ++k) mesh.X0.push_back(a + static_cast<double>(k) / n * (b - a));
  }
  const std::size_t m = mesh.X0.size();
  for (std::size_t k = 0; k < m; ++k) mesh.edges.push_back({k, k, (k + 1) % m});
  return mesh;
}

void run(double dp, sph::Correction correction, sph::SphFluid::Reaction reaction,
         const char* name) {
  sph::SphOptions o;
  o.rho0 = 1000.0, o.dp = dp, o.c0 = 20.0, o.viscosity = 1e-6, o.correction = correction;
  o.domain_min = {-0.2, -0.2}, o.domain_max = {0.4, 0.25};
  const sph::InterfaceBoundary body(
      outline({{0.06, -0.01}, {0.1, -0.01}, {0.1, 0.05}, {0.06, 0.05}}, 0.01), dp);
  const std::vector<sph::WallPoint> points = body.wall_points(1);
  sph::SphFluid fluid(o, sph::fill_rectangle({0.0, 0.0}, {0.04, 0.04}, dp), {}, points);
  fluid.set_velocities(std::vector<Vec2>(fluid.particles().size(), Vec2(1.0, 0.0)));
  fluid.track_wall_forces(0, reaction);
  const double M = 1000.0 * 0.04 * 0.06;
  const Vec2 P0 = fluid.momentum();
  Vec2 d = Vec2::Zero(), V = Vec2::Zero();
  double worst = 0.0;
  sph::WallParticles& w = fluid.moved_walls();
  while (fluid.time() < 0.04) {
    const double h = fluid.next_dt();
    d += V * h; // the body's translation over the step, its velocity the step's mean (eq. 17)
    for (std::size_t a = 0; a < points.size(); ++a) {
      for (int c = 0; c < 2; ++c)
        w.x[c][a] = points[a].x[c] + d[c], w.v[c][a] = V[c], w.a[c][a] = 0.0;
    }
    fluid.advance(h);
    Vec2 f = Vec2::Zero();
    for (std::size_t a = 0; a < points.size(); ++a) f += fluid.wall_force(a);
    V += f * h / M;
    worst = std::max(worst, (fluid.momentum() + M * V - P0).norm());
  }
  const double J = M * V.norm();
  const double drift = (fluid.momentum() + M * V - P0).norm();
  std::printf("%-15s %8.2e %6ld %10.4e %12.3e %12.3e %9zu\n", name, dp, fluid.steps(), J, drift / J,
              worst / J, fluid.removed());
}

} // namespace

int main(int argc, char** argv) {
  const double dp = argc > 1 ? std::atof(argv[1]) : 0.005;
  const bool none = argc > 2 && std::string(argv[2]) == "none";
  const sph::Correction c = none ? sph::Correction::none : sph::Correction::rkgc;
  std::printf("%-15s %8s %6s %10s %12s %12s %9s\n", "reaction", "dp", "steps", "|J| N s/m",
              "drift/|J|", "worst/|J|", "removed");
  run(dp, c, sph::SphFluid::Reaction::exact, "exact");
  run(dp, c, sph::SphFluid::Reaction::reference_code, "reference_code");
  return 0;
}
