// Particle sub-steps per second of the TL-SPH solid on the oscillating plate (L = 0.2, H = 0.02
// free, 0.06 clamped; E = 2 MPa, nu = 0.3975, rho = 1000; V_f = 0.05) at H/dp = 18 (4.3k
// particles) and 55 (39k), on 1 and 2 threads (omp_set_num_threads). One iteration is one
// velocity-Verlet sub-step at the stable dt_s; items/s is particles x sub-steps per second.
#include <benchmark/benchmark.h>

#include <cmath>
#include <map>
#include <memory>
#include <numbers>
#include <omp.h>

#include "solid_tlsph/solid.hpp"

using namespace fsi::tlsph;
using fsi::Vec2;

namespace {

std::unique_ptr<TlsphSolid> make_plate(int layers) {
  const double L = 0.2, H = 0.02, dp = H / layers;
  TlsphOptions o;
  o.material.youngs_modulus = 2.0e6;
  o.material.poisson_ratio = 0.3975;
  o.material.density = 1000.0;
  o.dp = dp;
  o.clamps.push_back({[](const Vec2& X) { return X.x() < 0.0; }, {}, {}});
  auto s = std::make_unique<TlsphSolid>(fill_rectangle({-0.06, -0.5 * H}, {L, 0.5 * H}, dp), o);
  // First mode (kL = 1.875) initial velocity, V_f = 0.05.
  const double kL = 1.8751040687119611, k = kL / L;
  const double M = std::sin(kL) + std::sinh(kL), N = std::cos(kL) + std::cosh(kL);
  auto f = [&](double x) {
    return M * (std::cos(k * x) - std::cosh(k * x)) - N * (std::sin(k * x) - std::sinh(k * x));
  };
  std::vector<Vec2> v(s->size(), Vec2::Zero());
  for (std::size_t i = 0; i < s->size(); ++i) {
    const double x = s->reference_position(i).x();
    if (x > 0.0) v[i] = Vec2(0.0, 0.05 * s->sound_speed() * f(x) / f(L));
  }
  s->set_velocities(v);
  return s;
}

void BM_substep(benchmark::State& state) {
  const int layers = static_cast<int>(state.range(0));
  omp_set_num_threads(static_cast<int>(state.range(1)));
  auto s = make_plate(layers);
  // Leave the initial transient: a few hundred sub-steps into the oscillation.
  for (int k = 0; k < 200; ++k) s->advance(s->time(), s->stable_dt());
  for (auto _ : state) s->advance(s->time(), s->stable_dt());
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(s->size()));
  state.counters["particles"] = static_cast<double>(s->size());
  state.counters["threads"] = static_cast<double>(state.range(1));
  state.counters["bytes/particle"] = static_cast<double>(s->fields().bytes_per_particle());
}

} // namespace

BENCHMARK(BM_substep)
    ->Args({18, 1})
    ->Args({18, 2})
    ->Args({55, 1})
    ->Args({55, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

BENCHMARK_MAIN();
