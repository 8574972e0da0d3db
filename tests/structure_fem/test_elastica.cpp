// Geometric nonlinearity: slender cantilever under a dead vertical end load against the elastica,
// and the quadratic convergence of Newton–Raphson.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "cantilever.hpp"
#include "fsi/core/error.hpp"

using namespace fem_test;
using Catch::Matchers::WithinAbs;

namespace {

struct ElasticaTip {
  double v, u; // deflection and horizontal shortening of the tip, over L
};

/// Elastica of a cantilever with a dead end load, k = P L^2 / EI: theta'' = -k cos(theta) on
/// s in [0, 1], theta(0) = 0, theta'(1) = 0; shooting on theta'(0) with RK4 and bisection.
ElasticaTip elastica(double k) {
  const int n = 4000;
  auto integrate = [&](double c, ElasticaTip* tip) {
    // y = (theta, theta', x, y)
    Eigen::Vector4d y(0.0, c, 0.0, 0.0);
    auto rhs = [&](const Eigen::Vector4d& z) {
      return Eigen::Vector4d(z[1], -k * std::cos(z[0]), std::cos(z[0]), std::sin(z[0]));
    };
    const double h = 1.0 / n;
    for (int i = 0; i < n; ++i) {
      const Eigen::Vector4d k1 = rhs(y), k2 = rhs(y + 0.5 * h * k1), k3 = rhs(y + 0.5 * h * k2),
                            k4 = rhs(y + h * k3);
      y += h / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4);
    }
    if (tip) *tip = {y[3], 1.0 - y[2]};
    return y[1]; // theta'(1)
  };
  double lo = 0.0, hi = k; // theta'(1) < 0 at c = 0, > 0 at c = k
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    (integrate(mid, nullptr) < 0.0 ? lo : hi) = mid;
  }
  ElasticaTip tip{};
  integrate(0.5 * (lo + hi), &tip);
  return tip;
}

/// Slender beam, plane stress, nu = 0, EI = 1 per unit thickness.
Beam slender_beam() {
  Beam b;
  b.L = 1.0, b.h = 0.01, b.nu = 0.0, b.rho = 1000.0;
  b.E = 12.0 / (b.h * b.h * b.h); // EI = E h^3 / 12 = 1
  b.plane = PlaneModel::plane_stress;
  b.ex = 100, b.ey = 2;
  return b;
}

} // namespace

TEST_CASE("fem: elastica reference reproduces Mattiasson's values", "[structure_fem][elastica]") {
  const ElasticaTip k1 = elastica(1.0), k10 = elastica(10.0);
  CHECK_THAT(k1.v, WithinAbs(0.30172, 2e-5));
  CHECK_THAT(k1.u, WithinAbs(0.05643, 2e-5));
  CHECK_THAT(k10.v, WithinAbs(0.81061, 2e-5));
  // Mattiasson's table gives u/L = 0.55500 at k = 10 (the issue quoted 0.55646, which neither
  // this shooting solution nor the table supports).
  CHECK_THAT(k10.u, WithinAbs(0.55500, 2e-5));
}

TEST_CASE("fem: slender cantilever under a dead end load follows the elastica",
          "[structure_fem][elastica]") {
  const Beam b = slender_beam();
  auto options = beam_options(b);
  Structure s(beam_mesh(b), options);
  const int tip = tip_node(s.mesh(), b);
  for (double k : {1.0, 2.0, 5.0, 10.0}) {
    const auto start = s.save();
    s.set_external_forces(tip_load(s.mesh(), b, k)); // P = k EI / L^2 with EI = L = 1
    s.solve_static({static_cast<int>(std::ceil(2 * k))});
    const ElasticaTip ref = elastica(k);
    const double v = -s.displacement()[2 * tip + 1], u = -s.displacement()[2 * tip];
    INFO("k = " << k << ": FEM v/L = " << v << ", u/L = " << u << "; elastica " << ref.v << ", "
                << ref.u);
    CHECK_THAT(v, Catch::Matchers::WithinRel(ref.v, 0.01));
    CHECK_THAT(u, Catch::Matchers::WithinRel(ref.u, 0.01));
    s.restore(start);
  }
}

TEST_CASE("fem: Newton–Raphson converges quadratically in a nonlinear step",
          "[structure_fem][newton]") {
  // From equilibrium at k = 2 (large rotation), a 10 % load increment: Newton starts near the
  // solution, where the consistent tangent must give quadratic convergence.
  Beam b = slender_beam();
  b.h = 0.1, b.E = 12.0 / (b.h * b.h * b.h); // L / h = 10 keeps the round-off floor low
  b.ex = 40, b.ey = 4;
  auto options = beam_options(b);
  options.newton.residual_rtol = 1e-13;
  options.newton.increment_rtol = 1e-8; // stop before a round-off iterate enters the order
  Structure s(beam_mesh(b), options);
  s.set_external_forces(tip_load(s.mesh(), b, 2.0));
  s.solve_static({4});
  s.set_external_forces(tip_load(s.mesh(), b, 2.2));
  const auto reports = s.solve_static({1});
  const auto& h = reports.back().history;
  std::string log;
  for (const auto& it : h) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3e ", it.residual_norm);
    log += buf;
  }
  INFO("residuals: " << log);
  // Observed order from the last three residuals above the round-off floor.
  std::vector<double> r;
  for (const auto& it : h)
    if (it.residual_norm > 1e-10 * h.front().residual_norm) r.push_back(it.residual_norm);
  REQUIRE(r.size() >= 3);
  const std::size_t n = r.size();
  const double order = std::log(r[n - 1] / r[n - 2]) / std::log(r[n - 2] / r[n - 3]);
  CHECK(order > 1.8);
}

TEST_CASE("fem: Newton failure is a RunError naming the step", "[structure_fem][newton]") {
  Beam b = slender_beam();
  b.ex = 20;
  auto options = beam_options(b);
  options.newton.max_iterations = 2;
  Structure s(beam_mesh(b), options);
  s.set_external_forces(tip_load(s.mesh(), b, 10.0));
  CHECK_THROWS_WITH(s.solve_static({1}),
                    Catch::Contains("Newton did not converge") && Catch::Contains("load step 1"));
}

TEST_CASE("fem: Newton ends at the round-off floor once the residual is met and the increment "
          "stops halving",
          "[structure_fem][newton]") {
  // An increment tolerance no double can meet (and the 1e-13 floor test off): the iteration can
  // only end by the stall test, with the residual met and the solution unchanged. L / h = 10:
  // the residual's round-off floor lies below its tolerance (at L / h = 100 it does not, and the
  // 1e-13 floor test ends the loop).
  Beam b = slender_beam();
  b.h = 0.1, b.E = 12.0 / (b.h * b.h * b.h);
  b.ex = 40, b.ey = 4;
  auto options = beam_options(b);
  options.newton.increment_rtol = 0.0;
  options.newton.increment_atol = 0.0;
  options.newton.roundoff_rtol = 0.0;
  options.newton.max_iterations = 40;
  Structure s(beam_mesh(b), options);
  s.set_external_forces(tip_load(s.mesh(), b, 1.0));
  const auto reports = s.solve_static({2});
  const int tip = tip_node(s.mesh(), b);
  const ElasticaTip ref = elastica(1.0);
  for (const auto& r : reports) {
    const auto& h = r.history;
    INFO("iterations " << r.iterations << ", last increments " << h[h.size() - 2].increment_norm
                       << ", " << h.back().increment_norm << ", residual " << r.final_residual);
    CHECK(r.roundoff_stops == 1);
    CHECK(r.iterations < 40);
    CHECK(h.back().increment_norm > 0.5 * h[h.size() - 2].increment_norm);
    CHECK(r.final_residual <=
          options.newton.residual_atol + options.newton.residual_rtol * h.front().residual_norm);
  }
  CHECK_THAT(-s.displacement()[2 * tip + 1], Catch::Matchers::WithinRel(ref.v, 0.02));
  // With the default tolerances the same load ends by the increment test, not at the floor.
  Structure d(beam_mesh(b), beam_options(b));
  d.set_external_forces(tip_load(d.mesh(), b, 1.0));
  for (const auto& r : d.solve_static({2})) CHECK(r.roundoff_stops == 0);
}
