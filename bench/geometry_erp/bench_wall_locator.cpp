// Nearest-wall queries per second for 100k particles against 100 and 10k segments, both locator
// back-ends, 1 and 2 threads; and the cost of update() after every node moved.
//
// Layouts (1.6 m x 1.0 m tank, l0 = sqrt(area / 100k) = 4 mm, r_e = 3.1 l0):
//   tank:      the tank outline cut into N segments, particles uniform in the tank;
//   obstacles: N / 10 decagons (radius 2 r_e) scattered in the tank, particles uniform in the tank.
#include "common/sweep.hpp"
#include "geometry_erp/wall_locator.hpp"

#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <random>

using namespace fsi;
using namespace fsi::erp;

namespace {

constexpr double width = 1.6, height = 1.0;
constexpr std::size_t particle_count = 100'000;
const double l0 = std::sqrt(width * height / particle_count);
const double r_e = 3.1 * l0;

WallSet make_walls(int layout, int segments) {
  WallSet walls;
  std::vector<Vec2> points;
  if (layout == 0) {
    const Vec2 corner[4] = {{0, 0}, {width, 0}, {width, height}, {0, height}};
    for (int side = 0; side < 4; ++side)
      for (int k = 0; k < segments / 4; ++k)
        points.push_back(corner[side] +
                         (corner[(side + 1) % 4] - corner[side]) * k / (segments / 4));
    walls.add_polyline(points, true, 0);
  } else {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int obstacle = 0; obstacle < segments / 10; ++obstacle) {
      const Vec2 centre(width * u(rng), height * u(rng));
      points.clear();
      for (int k = 10; k-- > 0;) // clockwise: fluid outside
        points.push_back(centre + 2.0 * r_e *
                                      Vec2(std::cos(0.2 * std::numbers::pi * k),
                                           std::sin(0.2 * std::numbers::pi * k)));
      walls.add_polyline(points, true, obstacle);
    }
  }
  return walls;
}

std::vector<Vec2> make_particles() {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec2> x(particle_count);
  for (Vec2& p : x) p = Vec2(width * u(rng), height * u(rng));
  return x;
}

/// Args: layout (0 tank, 1 obstacles), segments, back-end (0 grid, 1 AABB tree), threads.
void BM_query(benchmark::State& state) {
  const WallSet walls =
      make_walls(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  const auto kind = state.range(2) == 0 ? LocatorKind::grid : LocatorKind::aabb_tree;
  const int threads_before = fsi::num_threads();
  fsi::bench::use_threads(state, 3);
  const auto locator = make_wall_locator(walls, r_e, kind);
  const std::vector<Vec2> x = make_particles();
  WallHits hits;
  locator->query(x, hits); // warm-up: sizes the output
  for (auto _ : state) {
    locator->query(x, hits);
    benchmark::DoNotOptimize(hits.face[0].r.data());
    benchmark::ClobberMemory();
  }
  std::size_t near = 0;
  for (const int s : hits.face[0].segment) near += s >= 0;
  state.counters["near_wall"] = static_cast<double>(near) / static_cast<double>(x.size());
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * x.size()));
  fsi::set_num_threads(threads_before);
}

/// Args: layout, segments, back-end. Every node moves, then update() (timed together).
void BM_update(benchmark::State& state) {
  WallSet walls = make_walls(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  const auto kind = state.range(2) == 0 ? LocatorKind::grid : LocatorKind::aabb_tree;
  const auto locator = make_wall_locator(walls, r_e, kind);
  double sign = 1.0;
  for (auto _ : state) {
    for (Vec2& p : walls.nodes().x) p += sign * 1e-4 * Vec2(1.0, 0.5);
    sign = -sign;
    locator->update();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * walls.segments().size()));
}

} // namespace

BENCHMARK(BM_query)
    ->ArgNames({"layout", "segments", "aabb", "threads"})
    ->ArgsProduct({{0, 1}, {100, 10000}, {0, 1}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_update)
    ->ArgNames({"layout", "segments", "aabb"})
    ->ArgsProduct({{0, 1}, {100, 10000}, {0, 1}})
    ->Unit(benchmark::kMicrosecond);

BENCHMARK_MAIN();
