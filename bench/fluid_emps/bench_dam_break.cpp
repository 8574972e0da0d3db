// Particle-steps per second of the EMPS dam break (issue 4's benchmark case; issue 43's in 3-D),
// r_e = 3.1 l0, on 1 or 2 threads; neighbour-list rebuilds and reorderings are counted.
// - dam_break (2-D): a 1 m wide, 2 m high water column against the left wall of a 4 m wide tank,
//   l0 = 0.01 m (20,000 particles) or 0.005 m (80,000), timed after 0.1 s of collapse. vector:1
//   runs the pair sums' AVX-512 form where the CPU has it (the default), vector:0 the scalar form.
// - dam_break_3d: the same column 0.5 m deep (y) in a box tank of 12 triangles 4 x 0.5 x 3 m open
//   at the top (z up), the shipped wall (wall_model default), l0 = 0.5 m / 23 (97,336 particles)
//   or 0.5 m / 50 (1,000,000), timed after 10 steps, a fixed 10 steps.
// Counters: items/s = particle-steps per second; M_pairs_per_s = neighbour pairs (r < r_e) swept
// per second, items/s times the mean neighbours (the 2-D and 3-D pair loops compared); wall
// s_per_sim_s = wall-clock seconds of the timed loop per simulated second at the Courant number 0.2
// on c; ms_* the step's parts; rss_B_per_particle = the resident set's growth over the fluid's
// construction and warm-up per particle.
#include "common/rss.hpp"
#include "common/sweep.hpp"
#include "fluid_emps/emps_fluid.hpp"
#include "geometry_erp/box_walls.hpp"
#include "geometry_erp/fill.hpp"

#include <algorithm>
#include <benchmark/benchmark.h>
#include <chrono>
#include <cmath>

using namespace fsi;

namespace {

// c = 10 sqrt(2 g H) for the column's height H = 2 m; dt at the Courant number 0.2 on c.
const double kC = 10.0 * std::sqrt(2.0 * 9.81 * 2.0);

// Times the benchmark's steps of `fluid` from t and sets the counters.
template <int D>
void time_steps(benchmark::State& state, emps::BasicEmpsFluid<D>& fluid, double t, double dt,
                double rss0) {
  const double rss1 = bench::rss_bytes();
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
  state.counters["M_pairs_per_s"] = benchmark::Counter(
      static_cast<double>(steps) * n * fluid.mean_neighbours() / 1e6, benchmark::Counter::kIsRate);
  state.counters["wall_s_per_sim_s"] = wall.count() / (static_cast<double>(steps) * dt);
  state.counters["steps_per_list"] =
      static_cast<double>(steps) /
      static_cast<double>(std::max(1L, fluid.neighbour_builds() - builds_before));
  state.counters["rss_B_per_particle"] = (rss1 - rss0) / n;
  const auto share = [&](double a, double b) { return (a - b) / static_cast<double>(steps); };
  state.counters["ms_neighbour_list"] = 1e3 * share(after.neighbours, before.neighbours);
  state.counters["ms_walls"] = 1e3 * share(after.walls, before.walls);
  state.counters["ms_viscosity"] = 1e3 * share(after.viscosity, before.viscosity);
  state.counters["ms_density"] = 1e3 * share(after.density, before.density);
  state.counters["ms_gradient"] = 1e3 * share(after.pressure_gradient, before.pressure_gradient);
  state.counters["ms_other"] = 1e3 * share(after.other, before.other);
}

void dam_break(benchmark::State& state) {
  const double l0 = 1e-3 * static_cast<double>(state.range(0));
  bench::use_threads(state, 1);
  const double rss0 = bench::rss_bytes();
  erp::WallSet walls;
  const std::vector<Vec2> tank{{0.0, 3.0}, {0.0, 0.0}, {4.0, 0.0}, {4.0, 3.0}};
  walls.add_polyline(tank, false, 0);
  const auto positions =
      erp::fill_lattice({0, 0}, l0, {{{0, 0}, {1, 0}, {1, 2}, {0, 2}}}, {}, &walls);
  emps::FluidOptions o;
  o.density = 1000.0;
  o.viscosity = 1e-6;
  o.l0 = l0;
  o.sound_speed = kC;
  o.wall.contact.alpha_rep = 1e7;
  o.gravity = {0.0, -9.81};
  o.domain_min = {-0.1, -0.1};
  o.domain_max = {4.1, 3.1};
  o.vector_kernels = state.range(2) != 0;
  emps::EmpsFluid fluid(o, positions, walls);
  const double dt = 0.2 * l0 / o.sound_speed;
  double t = 0.0;
  for (; t < 0.1; t += dt) fluid.advance(t, dt); // warm-up: the collapse under way
  time_steps(state, fluid, t, dt, rss0);
}

void dam_break_3d(benchmark::State& state) {
  const int across = static_cast<int>(state.range(0)); // particles across the 0.5 m depth
  const double l0 = 0.5 / across;
  bench::use_threads(state, 1);
  const double rss0 = bench::rss_bytes();
  erp::TriangleWallSet walls;
  erp::add_box_tank(walls, Vec3::Zero(), Vec3(4.0, 0.5, 3.0), true, 0);
  walls.update();
  std::vector<Vec3> positions;
  for (int k = 0; k < 4 * across; ++k)
    for (int j = 0; j < across; ++j)
      for (int i = 0; i < 2 * across; ++i)
        positions.push_back(l0 * Vec3(i + 0.5, j + 0.5, k + 0.5));
  emps::FluidOptions3 o;
  emps::apply_wall_preset(o, emps::WallModel::standard);
  o.density = 1000.0;
  o.viscosity = 1e-6;
  o.l0 = l0;
  o.sound_speed = kC;
  o.wall.contact.alpha_rep = 1e5;
  o.gravity = Vec3(0.0, 0.0, -9.81);
  o.domain_min = Vec3::Constant(-0.1);
  o.domain_max = Vec3(4.1, 0.6, 3.1);
  emps::EmpsFluid3 fluid(o, positions, walls, false);
  const double dt = 0.2 * l0 / o.sound_speed;
  double t = 0.0;
  for (int s = 0; s < 10; ++s, t += dt) fluid.advance(t, dt); // warm-up: lists built, under way
  time_steps(state, fluid, t, dt, rss0);
}

void sizes_threads_vector(benchmark::internal::Benchmark* b) {
  for (const int l0_mm : {10, 5})
    for (const int threads : {1, 2})
      for (const int vector : {1, 0}) b->Args({l0_mm, threads, vector});
  b->Unit(benchmark::kMillisecond)->UseRealTime();
}

} // namespace

BENCHMARK(dam_break)->ArgNames({"l0_mm", "threads", "vector"})->Apply(sizes_threads_vector);
BENCHMARK(dam_break_3d)
    ->ArgNames({"across", "threads"})
    ->Args({23, 1})
    ->Args({23, 2})
    ->Args({50, 1})
    ->Args({50, 2})
    ->Iterations(10)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

BENCHMARK_MAIN();
