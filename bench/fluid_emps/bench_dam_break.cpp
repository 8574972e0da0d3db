// Particle-steps per second of the EMPS dam break (issue 4's benchmark case): a 1 m wide, 2 m high
// water column against the left wall of a 4 m wide tank, r_e = 3.1 l0, l0 = 0.01 m (20,000
// particles) or 0.005 m (80,000), on 1 or 2 threads. Steps are timed after 0.1 s of collapse
// (the surge has started; neighbour-list rebuilds and reorderings are counted). Counters: items/s
// = particle-steps per second; wall_s_per_sim_s = wall-clock seconds of the timed loop per
// simulated second at the Courant number 0.2 on c. vector:1 runs the pair sums' AVX-512 form
// where the CPU has it (the default), vector:0 the scalar form.
#include "common/sweep.hpp"
#include "fluid_emps/emps_fluid.hpp"
#include "geometry_erp/fill.hpp"

#include <benchmark/benchmark.h>
#include <chrono>
#include <cmath>

using namespace fsi;

namespace {

void dam_break(benchmark::State& state) {
  const double l0 = 1e-3 * static_cast<double>(state.range(0));
  bench::use_threads(state, 1);
  erp::WallSet walls;
  const std::vector<Vec2> tank{{0.0, 3.0}, {0.0, 0.0}, {4.0, 0.0}, {4.0, 3.0}};
  walls.add_polyline(tank, false, 0);
  const auto positions =
      erp::fill_lattice({0, 0}, l0, {{{0, 0}, {1, 0}, {1, 2}, {0, 2}}}, {}, &walls);
  emps::FluidOptions o;
  o.density = 1000.0;
  o.viscosity = 1e-6;
  o.l0 = l0;
  o.sound_speed = 10.0 * std::sqrt(2.0 * 9.81 * 2.0);
  o.wall.contact.alpha_rep = 1e7;
  o.gravity = {0.0, -9.81};
  o.domain_min = {-0.1, -0.1};
  o.domain_max = {4.1, 3.1};
  o.vector_kernels = state.range(2) != 0;
  emps::EmpsFluid fluid(o, positions, walls);
  const double dt = 0.2 * l0 / o.sound_speed;
  double t = 0.0;
  for (; t < 0.1; t += dt) fluid.advance(t, dt); // warm-up: the collapse under way
  const emps::StepTimes before = fluid.times();
  const long builds_before = fluid.neighbour_builds();
  long steps = 0;
  const auto wall0 = std::chrono::steady_clock::now();
  for (auto _ : state) {
    fluid.advance(t, dt);
    t += dt;
    ++steps;
  }
  const std::chrono::duration<double> wall = std::chrono::steady_clock::now() - wall0;
  const emps::StepTimes& after = fluid.times();
  const double n = static_cast<double>(fluid.particles().size());
  state.SetItemsProcessed(static_cast<int64_t>(static_cast<double>(steps) * n));
  state.counters["particles"] = n;
  state.counters["neighbours"] = fluid.mean_neighbours();
  state.counters["wall_s_per_sim_s"] = wall.count() / (static_cast<double>(steps) * dt);
  state.counters["steps_per_list"] =
      static_cast<double>(steps) / static_cast<double>(fluid.neighbour_builds() - builds_before);
  const auto share = [&](double a, double b) { return (a - b) / static_cast<double>(steps); };
  state.counters["ms_neighbour_list"] = 1e3 * share(after.neighbours, before.neighbours);
  state.counters["ms_walls"] = 1e3 * share(after.walls, before.walls);
  state.counters["ms_viscosity"] = 1e3 * share(after.viscosity, before.viscosity);
  state.counters["ms_density"] = 1e3 * share(after.density, before.density);
  state.counters["ms_gradient"] = 1e3 * share(after.pressure_gradient, before.pressure_gradient);
  state.counters["ms_other"] = 1e3 * share(after.other, before.other);
}

void sizes_threads_vector(benchmark::internal::Benchmark* b) {
  for (const int l0_mm : {10, 5})
    for (const int threads : {1, 2})
      for (const int vector : {1, 0}) b->Args({l0_mm, threads, vector});
  b->Unit(benchmark::kMillisecond)->UseRealTime();
}

} // namespace

BENCHMARK(dam_break)->ArgNames({"l0_mm", "threads", "vector"})->Apply(sizes_threads_vector);

BENCHMARK_MAIN();
