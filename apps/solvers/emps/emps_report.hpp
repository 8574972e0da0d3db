#pragma once
// The fluid's part of run.json, one form for 2-D and 3-D: counts, n0, the resolved options and
// this process's seconds per part of the step.
#include "decomposed_particles.hpp"
#include "fluid_emps/emps_fluid.hpp"
#include "fsi_app/output/json.hpp"
#include "fsi_app/output/json_options.hpp"

namespace fsi::app::emps_plugin {

/// The counts over every rank when decomposed (collective), and then the bytes every rank sent
/// for ghosts over the run.
template <int D>
JsonObject fluid_report(const emps::BasicEmpsFluid<D>& fluid, std::size_t initial,
                        const DecomposedParticles<D>& ranks) {
  JsonObject f;
  f.add("particles_initial", static_cast<long long>(initial))
      .add("particles", static_cast<long long>(ranks.global(fluid.owned())))
      .add("removed_particles", static_cast<long long>(ranks.global(fluid.removed())))
      .add("mean_neighbours", fluid.mean_neighbours())
      .add("n0", fluid.n0())
      .add("neighbour_list_builds", static_cast<long long>(fluid.neighbour_builds()));
  const emps::StepTimes& t = fluid.times();
  if (ranks.decomposed()) { // and each rank's own work: its parts of the step, net of waits
    JsonObject balance = ranks.balance(fluid.owned());
    balance.add("busy_seconds_min", ranks.min(t.busy()))
        .add("busy_seconds_max", ranks.max(t.busy()));
    f.add("halo_bytes", ranks.halo_bytes()).add("ranks", balance);
  }
  if (fluid.options().wall.gap_courant > 0)
    f.add("wall_gap_limited_steps", static_cast<long long>(fluid.gap_limited_steps()));
  emps::BasicFluidOptions<D> options = fluid.options(); // the visitor takes members by reference
  JsonOptions resolved; // every key as the run used it: the wall model's preset and each term
  emps::visit_options(options, resolved);
  f.add("options", resolved.object);
  JsonObject seconds; // this process's wall seconds per part of the step, net of its waits
  seconds.add("neighbours", t.neighbours)
      .add("walls", t.walls)
      .add("viscosity", t.viscosity)
      .add("density", t.density)
      .add("pressure_gradient", t.pressure_gradient)
      .add("other", t.other)
      .add("waited", t.waited);
  f.add("seconds", seconds);
  return f;
}

} // namespace fsi::app::emps_plugin
