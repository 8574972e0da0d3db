// Particle sub-steps per second of the TL-SPH solid on the oscillating plate (L = 0.2, H = 0.02
// free, 0.06 clamped; E = 2 MPa, nu = 0.3975, rho = 1000; V_f = 0.05) at H/dp = 18 (4.3k
// particles) and 55 (39k), on 1 and 2 threads (fsi::set_num_threads), with the library's
// defaults (quadratic correction, clamp at its face) and the paper's form (paper = 1). One
// iteration is one velocity-Verlet sub-step at the stable dt_s; items/s is particles x
// sub-steps per second; the counter dt_s is the sub-step (the defaults take ~ 2.6 x as many).
#include <benchmark/benchmark.h>

#include <cmath>
#include <map>
#include <memory>
#include <numbers>

#include "fsi/core/parallel.hpp"
#include "solid_tlsph/solid.hpp"

using namespace fsi::tlsph;
using fsi::Vec2;

namespace {

std::unique_ptr<TlsphSolid> make_plate(int layers, bool paper) {
  const double L = 0.2, H = 0.02, dp = H / layers;
  TlsphOptions o;
  o.material.youngs_modulus = 2.0e6;
  o.material.poisson_ratio = 0.3975;
  o.material.density = 1000.0;
  o.dp = dp;
  Clamp clamp;
  clamp.contains = [](const Vec2& X) { return X.x() < 0.0; };
  if (paper) o.gradient_correction = GradientCorrection::linear, clamp.odd_image = false;
  o.clamps.push_back(clamp);
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
  fsi::set_num_threads(static_cast<int>(state.range(1)));
  auto s = make_plate(layers, state.range(2) != 0);
  // Leave the initial transient: a few hundred sub-steps into the oscillation.
  for (int k = 0; k < 200; ++k) s->advance(s->time(), s->stable_dt());
  for (auto _ : state) s->advance(s->time(), s->stable_dt());
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(s->size()));
  state.counters["particles"] = static_cast<double>(s->size());
  state.counters["threads"] = static_cast<double>(state.range(1));
  state.counters["paper"] = static_cast<double>(state.range(2));
  state.counters["dt_s"] = s->stable_dt();
  state.counters["bytes/particle"] = static_cast<double>(s->fields().bytes_per_particle());
}

} // namespace

BENCHMARK(BM_substep)
    ->Args({18, 1, 0})
    ->Args({18, 2, 0})
    ->Args({55, 1, 0})
    ->Args({55, 2, 0})
    ->Args({18, 1, 1})
    ->Args({55, 1, 1})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

BENCHMARK_MAIN();
