// The viscous limit of stable_dt (docs/fluid_emps.md, "The time step"): the step's viscous
// terms, each alone, on a lattice with random velocities decay at 0.95 of the limit and grow at
// 1.3 times it. The viscosities are set so that the limit is c dt / l0 = 0.3, where the pressure
// terms are stable, and the Courant part of stable_dt(1) is larger.
#include "fluid_emps/emps_fluid.hpp"
#include "geometry_erp/fill.hpp"
#include "test_support.hpp"

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <random>

using namespace fsi;

namespace {

/// The viscosities alone: no gravity, no wall contact, the viscous sums' own rates.
struct Viscous {
  double nu = 0.0;    ///< kinematic viscosity (eq. 11, eq. 24's mirror term at walls)
  double alpha = 0.0; ///< artificial and approach viscosity, the same alpha
};

template <int D> emps::BasicFluidOptions<D> options(double l0, const Viscous& v) {
  auto o = emps::test::water<D>(l0, -1.0, 2.0);
  o.viscosity = v.nu;
  o.artificial_viscosity = v.alpha;
  o.wall.mirror.approach_viscosity = v.alpha;
  return o;
}

/// Kinetic energy after `steps` steps of dt over that of the start, the particles at rest on
/// the lattice (x = l0 (m + 1/2)) given velocities of order 1e-9 c (every term linear): each flip
/// mode (-1)^(kappa . m), kappa in {0, 1}^D, with a random polarisation, and a tenth of that at
/// random.
template <int D, class Make> double energy_ratio(const Make& make, double dt, int steps) {
  auto fluid = make();
  std::mt19937 random(7);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  std::array<VecD<D>, 1 << D> flips;
  for (auto& g : flips)
    for (int a = 0; a < D; ++a) g[a] = u(random);
  const auto& x = fluid->particles().position;
  const double l0 = fluid->options().l0, speed = 1e-9 * fluid->options().sound_speed;
  std::vector<VecD<D>> v(fluid->owned());
  for (std::size_t i = 0; i < v.size(); ++i) {
    for (int a = 0; a < D; ++a) v[i][a] = 0.1 * u(random);
    for (int f = 1; f < (1 << D); ++f) {
      int parity = 0;
      for (int a = 0; a < D; ++a)
        parity += (f >> a & 1) * static_cast<int>(std::floor(x[a][i] / l0));
      v[i] += (parity % 2 == 0 ? 1.0 : -1.0) * flips[static_cast<std::size_t>(f)];
    }
    v[i] *= speed;
  }
  fluid->set_velocities(v);
  const double start = fluid->kinetic_energy();
  for (int k = 0; k < steps; ++k) fluid->advance(k * dt, dt);
  return fluid->kinetic_energy() / start;
}

/// The viscosity for which the limit is c dt / l0 = 0.3 (the limit goes as 1 / nu, 1 / alpha).
template <int D, class Make> double scaled(const Make& make, double probe) {
  const auto fluid = make(probe);
  const double dt = fluid->stable_dt(1.0);
  REQUIRE(dt < fluid->options().l0 / fluid->options().sound_speed); // the viscous limit binds
  return probe * dt * fluid->options().sound_speed / (0.3 * fluid->options().l0);
}

/// Each viscous term alone, eq. 11 (with eq. 24 at walls) and the closing pairs, at its limit.
template <int D, class Make> void check_limits(const Make& make) {
  for (const bool by_nu : {true, false}) {
    const auto with = [&](double x) { return make(by_nu ? Viscous{x, 0.0} : Viscous{0.0, x}); };
    const auto fluid = with(scaled<D>(with, 10.0));
    const Viscous v{fluid->options().viscosity, fluid->options().artificial_viscosity};
    const double dt = fluid->stable_dt(1.0), l0 = fluid->options().l0;
    CHECK_THAT(fluid->options().sound_speed * dt / l0, Catch::Matchers::WithinRel(0.3, 1e-12));
    const auto at = [&] { return make(v); };
    const double below = energy_ratio<D>(at, 0.95 * dt, 40);
    const double above = energy_ratio<D>(at, 1.3 * dt, 40);
    INFO("nu = " << v.nu << " m^2/s, alpha = " << v.alpha << ": E(40 steps)/E(0) " << below
                 << " at 0.95 dt, " << above << " at 1.3 dt");
    CHECK(below < 1.0);
    // On the lattice the peak mode grows by |1 - 1.3 * 2| = 1.6 a step. The closing pairs'
    // growth can stop where a reversal leaves every pair opening (the free cube: 6 times its
    // energy).
    CHECK(above > 2.0);
  }
}

} // namespace

TEST_CASE("emps: the viscous terms alone decay below stable_dt's limit and grow at 1.3 times it "
          "(2-D, closed box)",
          "[emps]") {
  // 24 x 24 particles in a closed box: the eq. 24 mirror term (no-slip) and the approach
  // viscosity across the walls, alpha_w = alpha so that every closing pair has the limit's alpha.
  const double l0 = 0.01, L = 24 * l0;
  erp::WallSet walls;
  const std::vector<Vec2> box{{0.0, 0.0}, {L, 0.0}, {L, L}, {0.0, L}};
  walls.add_polyline(box, true, 0);
  const auto positions = erp::fill_lattice({0, 0}, l0, {box}, {}, &walls);
  REQUIRE(positions.size() == 576);
  const auto make = [&](const Viscous& v) {
    return std::make_unique<emps::EmpsFluid>(options<2>(l0, v), positions, walls);
  };
  check_limits<2>(make);
}

TEST_CASE("emps: the viscous terms alone decay below stable_dt's limit and grow at 1.3 times it "
          "(3-D, the cubic lattice)",
          "[emps]") {
  // A free 16^3 cube (no walls): its interior is the cubic lattice of the limit.
  const double l0 = 0.01;
  const erp::TriangleWallSet no_walls;
  const auto positions = emps::test::block(16, 16, 16, l0);
  const auto make = [&](const Viscous& v) {
    return std::make_unique<emps::EmpsFluid3>(options<3>(l0, v), positions, no_walls);
  };
  check_limits<3>(make);
}
