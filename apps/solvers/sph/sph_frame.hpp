#pragma once
// What the SPH models (SphModel, SphModel3) read off their fluid, one form for 2-D and 3-D and
// for one process or many (decomposed_particles.hpp): the frame's particles (the fluid's own, or
// every rank's owned ones gathered to rank 0 in id order), the mean speed and run.json's block.
#include "decomposed_particles.hpp"
#include "fluid_sph/sph_fluid.hpp"
#include "fsi_app/output/json.hpp"

#include <array>
#include <cmath>
#include <cstddef>

namespace fsi::app::sph_plugin {

/// Read-only arrays of n particles (positions and velocities by axis).
template <int D> struct SphFrame {
  std::size_t n = 0;
  std::array<const double*, D> x{}, v{};
  const double *p = nullptr, *rho = nullptr, *det_a = nullptr;
};

/// Values a gathered particle: id, x, v, p, rho, |A|.
template <int D> inline constexpr std::size_t kFrameValues = 2 * D + 4;

/// Collective: the first `owned` particles of `f` on every rank to rank 0, sorted by id.
template <int D>
void gather_frame(DecomposedParticles<D>& ranks, const sph::BasicSphFluid<D>& fluid) {
  const auto& f = fluid.particles();
  ranks.gather(fluid.owned(), kFrameValues<D>, [&](std::size_t i, double* row) {
    row[0] = f.id[i];
    for (int a = 0; a < D; ++a) row[1 + a] = f.x[a][i], row[1 + D + a] = f.v[a][i];
    row[1 + 2 * D] = f.p[i], row[2 + 2 * D] = f.rho[i], row[3 + 2 * D] = f.det_a[i];
  });
}

/// The particles a frame reads: decomposed, the last gather's (none on ranks other than 0);
/// otherwise every particle of the fluid, in its own order.
template <int D>
SphFrame<D> frame(const DecomposedParticles<D>& ranks, const sph::BasicSphFluid<D>& fluid) {
  SphFrame<D> s;
  if (!ranks.decomposed()) {
    const auto& f = fluid.particles();
    s.n = f.size();
    for (int a = 0; a < D; ++a) s.x[a] = f.x[a].data(), s.v[a] = f.v[a].data();
    s.p = f.p.data(), s.rho = f.rho.data(), s.det_a = f.det_a.data();
    return s;
  }
  s.n = ranks.gathered();
  for (std::size_t a = 0; a < D; ++a)
    s.x[a] = ranks.column(1 + a), s.v[a] = ranks.column(1 + D + a);
  s.p = ranks.column(1 + 2 * D), s.rho = ranks.column(2 + 2 * D), s.det_a = ranks.column(3 + 2 * D);
  return s;
}

/// Collective: the mean |v| over every rank's owned particles.
template <int D>
double mean_speed(const DecomposedParticles<D>& ranks, const sph::BasicSphFluid<D>& fluid) {
  const auto& f = fluid.particles();
  double speeds = 0.0;
  for (std::size_t i = 0; i < fluid.owned(); ++i) {
    if constexpr (D == 2) {
      speeds += std::hypot(f.v[0][i], f.v[1][i]);
    } else {
      speeds += std::sqrt(f.v[0][i] * f.v[0][i] + f.v[1][i] * f.v[1][i] + f.v[2][i] * f.v[2][i]);
    }
  }
  const std::size_t n = ranks.global(fluid.owned());
  return n ? ranks.sum(speeds) / static_cast<double>(n) : 0.0;
}

/// Collective: run.json's fluid block, counts over every rank (decomposed: and the ghosts).
template <int D>
JsonObject fluid_report(const DecomposedParticles<D>& ranks, const sph::BasicSphFluid<D>& fluid,
                        std::size_t initial, std::size_t first_point) {
  JsonObject f;
  f.add("particles_initial", static_cast<long long>(initial))
      .add("particles", static_cast<long long>(ranks.global(fluid.owned())))
      .add("removed_particles", static_cast<long long>(ranks.global(fluid.removed())))
      .add("wall_particles", static_cast<long long>(fluid.walls().size()))
      .add("interface_points", static_cast<long long>(fluid.walls().size() - first_point))
      .add("mean_neighbours", fluid.mean_neighbours())
      .add("acoustic_steps", static_cast<long long>(fluid.steps()))
      .add("advection_steps", static_cast<long long>(fluid.advection_steps()));
  if (ranks.decomposed()) { // every rank's ghosts at the end (the halo of the last pair build)
    f.add("ghosts", static_cast<long long>(ranks.global(fluid.particles().size() - fluid.owned())));
    f.add("halo_bytes", ranks.halo_bytes()); // sent over the run, every rank's
    f.add("ranks", ranks.balance(fluid.owned()));
  }
  return f;
}

} // namespace fsi::app::sph_plugin
