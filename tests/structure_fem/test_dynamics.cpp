// Dynamics: first natural frequency, energy conservation and numerical damping of Newmark-beta,
// save/restore and the predictor.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <vector>

#include "cantilever.hpp"
#include "fsi/core/error.hpp"
#include "fsi/core/parallel.hpp"
#include "sequential.hpp"

using namespace fem_test;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

/// First bending frequency of a clamped-free Euler–Bernoulli beam [rad/s].
double euler_bernoulli_omega1(const Beam& b) {
  const double beta1 = 1.8751040687; // root of cos x cosh x = -1
  const double I = b.h * b.h * b.h / 12.0;
  return beta1 * beta1 * std::sqrt(bending_modulus(b) * I / (b.rho * b.h)) / (b.L * b.L);
}

/// Releases the beam from its static deflection under a small tip load P.
void release_from_tip_load(Structure& s, const Beam& b, double P) {
  s.set_external_forces(tip_load(s.mesh(), b, P));
  s.solve_static();
  s.set_external_forces(Vector::Zero(2 * static_cast<Eigen::Index>(s.num_nodes())));
  s.update_acceleration();
}

/// Times at which the tip deflection crosses zero upwards (linear interpolation).
std::vector<double> upward_crossings(Structure& s, int tip, double dt, int steps) {
  std::vector<double> t;
  double y_prev = s.displacement()[2 * tip + 1];
  for (int i = 0; i < steps; ++i) {
    s.advance(dt);
    const double y = s.displacement()[2 * tip + 1];
    if (y_prev < 0.0 && y >= 0.0) t.push_back(s.time() - dt * y / (y - y_prev));
    y_prev = y;
  }
  return t;
}

} // namespace

TEST_CASE("fem: first natural frequency from a free-vibration time history",
          "[structure_fem][dynamics]") {
  const fem_test::Sequential sequential;
  Beam b;
  b.h = 0.05, b.E = 1.0e7, b.rho = 1000.0, b.ex = 40, b.ey = 2; // L / h = 20
  auto o = beam_options(b);
  o.newmark = {0.25, 0.5}; // no numerical damping; period error (omega dt)^2 / 12 ~ 3e-4
  Structure s(beam_mesh(b), o);
  release_from_tip_load(s, b, 1e-3 * b.E * std::pow(b.h, 3) / 12.0); // tip ~ 3e-4 L
  const double omega = euler_bernoulli_omega1(b), T = 2.0 * std::numbers::pi / omega;
  const auto t = upward_crossings(s, tip_node(s.mesh(), b), T / 100.0, 450);
  REQUIRE(t.size() >= 4);
  const double period = (t.back() - t.front()) / static_cast<double>(t.size() - 1);
  WARN("first period: FEM " << period << " s, Euler–Bernoulli " << T << " s");
  CHECK_THAT(period, WithinRel(T, 0.02));
}

TEST_CASE("fem: Newmark energy: conserved with beta = 1/4, decaying with the paper's default",
          "[structure_fem][dynamics][energy]") {
  const fem_test::Sequential sequential;
  Beam b;
  b.h = 0.1, b.E = 1.0e7, b.rho = 1000.0, b.ex = 8, b.ey = 1; // coarse: runs in seconds
  const double omega = euler_bernoulli_omega1(b), T = 2.0 * std::numbers::pi / omega;
  const double dt = T / 40.0;
  const int periods = 100;
  auto run = [&](NewmarkOptions newmark) {
    auto o = beam_options(b);
    o.newmark = newmark;
    o.newton.residual_rtol = 1e-12;
    o.newton.increment_rtol = 1e-12;
    Structure s(beam_mesh(b), o);
    release_from_tip_load(s, b, 1e-4 * b.E * std::pow(b.h, 3) / 12.0);
    // Mechanical energy relative to the released state: the static load's work is bookkeeping.
    const double E0 = s.energies().kinetic + s.energies().strain, shift = s.energies().total() - E0;
    std::vector<double> energy{E0};
    for (int p = 0; p < periods; ++p) {
      for (int i = 0; i < 40; ++i) s.advance(dt);
      energy.push_back(s.energies().total() - shift);
    }
    return energy;
  };
  const auto trapezoidal = run({0.25, 0.5});
  double drift = 0.0;
  for (double e : trapezoidal)
    drift = std::max(drift, std::abs(e - trapezoidal[0]) / trapezoidal[0]);
  WARN("beta = 1/4, gamma = 1/2: largest relative energy change over " << periods << " periods "
                                                                       << drift);
  CHECK(drift < 1e-3);

  const auto damped = run({});
  const double decay = std::log(damped[0] / damped[10]) / 10.0; // per period, first 10 periods
  WARN("beta = 0.3025, gamma = 0.6: energy decay rate "
       << decay << " per period (E_100 / E_0 = " << damped.back() / damped[0] << ")");
  CHECK(decay > 0.0);
  CHECK(damped.back() < damped[0]);
  for (std::size_t p = 1; p < damped.size(); ++p) CHECK(damped[p] <= damped[p - 1] * (1 + 1e-12));
}

TEST_CASE("fem: save/restore re-runs a step bit for bit; predictor follows eqs. 63-65",
          "[structure_fem][dynamics]") {
  Beam b;
  b.h = 0.1, b.E = 1.0e7, b.rho = 1000.0, b.ex = 10, b.ey = 2;
  auto o = beam_options(b);
  o.gravity = {0.0, -9.81};
  Structure s(beam_mesh(b), o);
  const double dt = 1e-3;
  for (int i = 0; i < 5; ++i) s.advance(dt);
  const StructureState saved = s.save();
  const Prediction pred = s.predict(dt);
  const Vector f = tip_load(s.mesh(), b, 50.0);
  s.set_external_forces(f);
  s.advance(dt);
  const Vector u1 = s.displacement(), v1 = s.velocity(), a1 = s.acceleration();
  s.set_external_forces(2.0 * f);
  s.advance(dt);
  s.restore(saved);
  CHECK(s.time() == saved.time);
  s.set_external_forces(f);
  const StepReport& report = s.advance(dt);
  CHECK(report.iterations >= 1);
  CHECK(report.history.size() == static_cast<std::size_t>(report.iterations));
  CHECK((s.displacement() - u1).norm() == 0.0);
  CHECK((s.velocity() - v1).norm() == 0.0);
  CHECK((s.acceleration() - a1).norm() == 0.0);

  const int k = tip_node(s.mesh(), b);
  const auto& st = saved;
  CHECK_THAT(
      pred.u[2 * k + 1],
      WithinAbs(st.u[2 * k + 1] + dt * st.v[2 * k + 1] + 0.5 * dt * dt * st.a[2 * k + 1], 1e-15));
  CHECK_THAT(pred.v[2 * k + 1], WithinAbs(st.v[2 * k + 1] + dt * st.a[2 * k + 1], 1e-15));
  CHECK(pred.a[2 * k + 1] == st.a[2 * k + 1]);
  // Gravity: starting at rest, a^0 solves M a = f_g; far from the clamp a = g (the consistent
  // mass couples the clamped dofs, so only up to a tiny decaying correction).
  Structure fresh(beam_mesh(b), o);
  CHECK_THAT(fresh.acceleration()[2 * k + 1], WithinRel(-9.81, 1e-6));
}

TEST_CASE("fem: options out of range are InputErrors naming the field",
          "[structure_fem][options]") {
  const Beam b;
  auto bad = beam_options(b);
  bad.material.poisson_ratio = 0.5;
  CHECK_THROWS_WITH(Structure(beam_mesh(b), bad), Catch::Contains("poisson_ratio"));
  bad = beam_options(b);
  bad.newmark.gamma = 0.4;
  CHECK_THROWS_WITH(Structure(beam_mesh(b), bad), Catch::Contains("gamma"));
  bad = beam_options(b);
  bad.clamped = {{"root", true, true, {}}};
  CHECK_THROWS_WITH(Structure(beam_mesh(b), bad), Catch::Contains("root"));
  Structure s(beam_mesh(b), beam_options(b));
  CHECK_THROWS_AS(s.set_external_forces(Vector::Zero(3)), fsi::InputError);
  CHECK_THROWS_AS(s.advance(0.0), fsi::InputError);
}
