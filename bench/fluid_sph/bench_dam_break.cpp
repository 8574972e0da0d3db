// Fluid-particle acoustic steps per second of the Riemann-SPH dam break (issue 18's benchmark;
// issue 45's in 3-D), rkgc on, 1 or 2 threads; advection-step work (pair rebuild, sort, density,
// B, viscous force) is counted.
// - dam_break (2-D): a 1 m wide, 2 m high water column against the left wall of a 4 m wide tank,
//   dp = 0.01 m (20,000 particles) or 0.005 m (80,000); timed after 0.1 s of collapse.
// - dam_break_3d: the same column 0.5 m deep (y) in an open box tank 4 x 0.5 x 3 m (z up), about
//   100,000 or 1,000,000 particles (dp = (1 m^3 / N)^(1/3)); timed after 0.02 s of collapse, a
//   fixed 10 steps (Google Benchmark would otherwise rerun the warm-up while it sizes the count).
// FSI_SPH_WARMUP=seconds overrides the collapse before timing. Counters: items/s = fluid-particle
// acoustic steps per second; wall_s_per_sim_s = wall-clock seconds of the timed loop per
// simulated second; rss_MB = the process's resident set after the warm-up; rss_B_per_particle
// its growth from before the fluid was built, per fluid particle (wall dummies included in it).
#include "common/rss.hpp"
#include "dam_break_options.hpp"
#include "fluid_sph/sph_fluid.hpp"
#include "fsi/core/parallel.hpp"

#include <benchmark/benchmark.h>
#include <chrono>
#include <cmath>
#include <cstdlib>

using namespace fsi;
using fsi::bench::rss_bytes;

namespace {

// The column's speed scales: c0 = 10 sqrt(2 g H), u_ref = 2 sqrt(g H), H = 2 m.
const double kC0 = 10.0 * std::sqrt(2.0 * 9.81 * 2.0), kURef = 2.0 * std::sqrt(9.81 * 2.0);

// Warms `fluid` up, times the benchmark's steps and sets the counters.
template <int D>
void time_steps(benchmark::State& state, sph::BasicSphFluid<D>& fluid, double rss0, double warmup) {
  const char* warm = std::getenv("FSI_SPH_WARMUP");
  fluid.advance_to(warm ? std::atof(warm) : warmup);
  const double rss1 = rss_bytes();
  const long steps0 = fluid.steps(), builds0 = fluid.advection_steps();
  const double t0 = fluid.time();
  const auto wall0 = std::chrono::steady_clock::now();
  for (auto _ : state) fluid.advance(fluid.next_dt());
  const std::chrono::duration<double> wall = std::chrono::steady_clock::now() - wall0;
  const double n = static_cast<double>(fluid.particles().size());
  const double steps = static_cast<double>(fluid.steps() - steps0);
  state.SetItemsProcessed(static_cast<int64_t>(steps * n));
  state.counters["particles"] = n;
  state.counters["walls"] = static_cast<double>(fluid.walls().size());
  state.counters["neighbours"] = fluid.mean_neighbours();
  state.counters["acoustic_per_advection"] =
      steps / static_cast<double>(std::max(1L, fluid.advection_steps() - builds0));
  state.counters["sim_s"] = fluid.time() - t0;
  state.counters["wall_s_per_sim_s"] = wall.count() / (fluid.time() - t0);
  state.counters["rss_MB"] = rss1 / 1e6;
  state.counters["rss_B_per_particle"] = (rss1 - rss0) / n;
  state.counters["fields_B_per_particle"] =
      static_cast<double>(fluid.particles().fields.bytes_per_particle());
}

void dam_break(benchmark::State& state) {
  const double dp = 1e-3 * static_cast<double>(state.range(0));
  set_num_threads(static_cast<int>(state.range(1)));
  const double rss0 = rss_bytes();
  const sph::SphOptions o = sph::dam_break_options<2>(dp, kC0, kURef, {-0.1, -0.1}, {4.1, 3.1});
  const std::vector<sph::WallPolyline> walls{{{{0.0, 3.0}, {0.0, 0.0}, {4.0, 0.0}, {4.0, 3.0}}}};
  sph::SphFluid fluid(o, sph::fill_rectangle({0, 0}, {1, 2}, dp), walls);
  time_steps(state, fluid, rss0, 0.1);
}

void dam_break_3d(benchmark::State& state) {
  const double dp = std::cbrt(1.0 / (1e3 * static_cast<double>(state.range(0))));
  set_num_threads(static_cast<int>(state.range(1)));
  const double rss0 = rss_bytes();
  const sph::SphOptions3 o =
      sph::dam_break_options<3>(dp, kC0, kURef, {-0.1, -0.1, -0.1}, {4.1, 0.6, 3.1});
  sph::SphFluid3 fluid(o, sph::fill_box({0, 0, 0}, {1, 0.5, 2}, dp),
                       sph::box_walls({0, 0, 0}, {4, 0.5, 3}, dp));
  time_steps(state, fluid, rss0, 0.02);
}

} // namespace

BENCHMARK(dam_break)
    ->ArgNames({"dp_mm", "threads"})
    ->Args({10, 1})
    ->Args({10, 2})
    ->Args({5, 1})
    ->Args({5, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

BENCHMARK(dam_break_3d)
    ->ArgNames({"kparticles", "threads"})
    ->Args({100, 1})
    ->Args({100, 2})
    ->Args({1000, 1})
    ->Args({1000, 2})
    ->Iterations(10)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

BENCHMARK_MAIN();
