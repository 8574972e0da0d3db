// Issue 4, test 1, on the shipped scene: still water 0.5 m deep (40 particles over H) in a rigid
// tank, damped over its first 2 s as the scene states, run to 10 s. The kinetic energy never
// rises above its value at the end of the damping phase; the bottom row's pressure, averaged over
// the last second, is within 3 % of rho g H; the mean speed at 10 s is below 1 % of sqrt(g H);
// no particle ends behind a wall (advance throws) or leaves the tank.
#include "emps/emps_model.hpp"
#include "fsi_app/scene.hpp"
#include "scene_probes.hpp"

#include <catch2/catch.hpp>
#include <cmath>

using namespace fsi;
using namespace fsi::app;
using fsi::app::emps_plugin::EmpsModel;
using fsi::app::emps_plugin::FluidSpec;
using fsi::app::test::named;

TEST_CASE("apps: the hydrostatic tank settles: bottom pressure, speed and energy at 10 s",
          "[apps][fluid]") {
  const Scene scene = load_scene(FSI_SOURCE_DIR "/data/scenes/hydrostatic_tank.yaml", {});
  const ProbeSpec &p_bottom = named(scene, "p_bottom"), &speed = named(scene, "mean_speed"),
                  &energy = named(scene, "kinetic_energy");
  EmpsModel model(scene);
  const FluidSpec& fluid = scene.fluid->as<FluidSpec>();
  const std::size_t particles = model.fluid().particles().size();
  const double dt = *scene.time.dt, t_damped = fluid.options.damping_time;
  const long steps = std::lround(scene.time.end / dt);
  const long every = std::lround(scene.output.interval / dt); // probes.csv's sampling
  const double rho_g_h = fluid.options.density * -scene.gravity.y() * 0.5;

  double energy_damped = -1.0, energy_max = 0.0, pressure_sum = 0.0;
  long pressure_samples = 0;
  for (long k = 0; k < steps; ++k) {
    model.advance(static_cast<double>(k) * dt, dt);
    const double t = static_cast<double>(k + 1) * dt;
    if ((k + 1) % every != 0) continue;
    if (std::abs(t - t_damped) < 0.5 * dt) energy_damped = *model.probe(energy);
    if (t > t_damped + 0.5 * dt) energy_max = std::max(energy_max, *model.probe(energy));
    if (t > scene.time.end - 1.0 - 0.5 * dt)
      pressure_sum += *model.probe(p_bottom), ++pressure_samples;
  }
  const double pressure = pressure_sum / static_cast<double>(pressure_samples);
  const double mean_speed = *model.probe(speed);
  INFO("p_bottom " << pressure << " Pa against rho g H " << rho_g_h << " Pa; mean speed "
                   << mean_speed << " m/s; kinetic energy " << energy_damped << " J/m at "
                   << t_damped << " s, largest after " << energy_max << " J/m");
  CHECK(t_damped > 0.0);
  CHECK(energy_damped > 0.0);
  CHECK(energy_max <= energy_damped);
  CHECK(std::abs(pressure / rho_g_h - 1.0) < 0.03);
  CHECK(mean_speed < 0.01 * std::sqrt(9.81 * 0.5));
  CHECK(model.fluid().particles().size() == particles);
}
