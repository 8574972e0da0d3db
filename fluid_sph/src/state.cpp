// The fluid's state: save and restore in memory, write and read a checkpoint (the pairs rebuilt
// from the restored build positions).
#include "fluid_sph/sph_fluid.hpp"

#include "fsi/core/error.hpp"
#include "fsi/core/parallel.hpp"
#include "fsi/core/state_archive.hpp"
#include "particles/state_rows.hpp"

#include <algorithm>
#include <cstdint>

namespace fsi::sph {

// Decomposed (issue 47): the owned particles only; restore() remakes the halo, as the step being
// redone may have migrated particles and rebuilt it since (EMPS's restore does the same).
template <int D> void BasicSphFluid<D>::save(State& s) const {
  fluid_.fields.save(s.fluid, owned());
  walls_.fields.save(s.walls);
  s.t = t_, s.Dt = Dt_, s.elapsed = elapsed_, s.dt_acoustic = dt_acoustic_;
  s.step = step_, s.builds = builds_, s.sub = sub_, s.subs = subs_, s.removed = removed_;
}

template <int D> void BasicSphFluid<D>::restore(const State& s) {
  hook().drop_ghosts(fluid_.fields);
  fluid_.fields.restore(s.fluid);
  walls_.fields.restore(s.walls);
  t_ = s.t, Dt_ = s.Dt, elapsed_ = s.elapsed, dt_acoustic_ = s.dt_acoustic;
  step_ = s.step, builds_ = s.builds, sub_ = s.sub, subs_ = s.subs, removed_ = s.removed;
  if (decomposition_) { // as decompose(): partitioned at the advection step's build positions
    hook().migrate(fluid_.fields, fluid_.xb, nullptr);
    build_ghosts(fluid_.xb);
  }
  build_pairs(false); // the restored advection step's pairs, from its build positions (checked)
  parallel_for(fluid_.size(), [&](std::size_t i) {
    fluid_.p[i] = options_.c0 * options_.c0 * (fluid_.rho[i] - options_.rho0);
  });
}

// One process: the arrays in the particles' order. Decomposed (collective): every process's
// owned particles gathered to process 0 in id order, the one-process format (issue 47), whose
// archive alone is whole; the tracked walls' viscous force and the removed count summed over the
// processes (each holds its particles' part).
template <int D>
void BasicSphFluid<D>::write_state(StateArchive& a, const std::string& prefix) const {
  if (decomposition_) {
    StateArchive rows;
    fluid_.fields.write_state(rows, prefix + "fluid/", owned());
    particles::gather_rows(hook(), rows, prefix + "fluid/id", a);
  } else {
    fluid_.fields.write_state(a, prefix + "fluid/");
  }
  walls_.fields.write_state(a, prefix + "walls/");
  if (decomposition_ && tracked_ < walls_.size()) {
    // Every component's tracked entries in one sum: [x entries, y entries (, z entries)].
    const std::size_t n = walls_.size() - tracked_;
    std::vector<double> sum;
    for (int c = 0; c < D; ++c)
      sum.insert(sum.end(), walls_.fv[c].begin() + static_cast<std::ptrdiff_t>(tracked_),
                 walls_.fv[c].end());
    hook().sum(sum);
    for (int c = 0; c < D; ++c) {
      std::vector<double> fv = walls_.fv[c];
      std::copy_n(sum.begin() + static_cast<std::ptrdiff_t>(c * n), n,
                  fv.begin() + static_cast<std::ptrdiff_t>(tracked_));
      a.put(prefix + "walls/fv" + "xyz"[c], std::move(fv));
    }
  }
  const auto removed = static_cast<std::int64_t>(hook().sum(static_cast<double>(removed_)));
  a.put(prefix + "clock", std::vector<double>{t_, Dt_, elapsed_, dt_acoustic_});
  a.put(prefix + "counters", std::vector<std::int64_t>{step_, builds_, sub_, subs_, removed});
}

template <int D>
void BasicSphFluid<D>::read_state(const StateArchive& a, const std::string& prefix) {
  const std::size_t nw = walls_.size();
  const auto& clock = a.reals(prefix + "clock", 4);
  const auto& counters = a.integers(prefix + "counters", 5);
  fluid_.fields.read_state(a, prefix + "fluid/");
  walls_.fields.read_state(a, prefix + "walls/");
  if (walls_.size() != nw)
    throw InputError("checkpoint: '" + prefix + "walls/' has " + std::to_string(walls_.size()) +
                     " wall particles, this scene has " + std::to_string(nw));
  t_ = clock[0], Dt_ = clock[1], elapsed_ = clock[2], dt_acoustic_ = clock[3];
  step_ = counters[0], builds_ = counters[1], sub_ = counters[2], subs_ = counters[3];
  removed_ = static_cast<std::size_t>(counters[4]);
  build_pairs(false); // as restore: the pairs were checked when first built
  parallel_for(fluid_.size(), [&](std::size_t i) {
    fluid_.p[i] = options_.c0 * options_.c0 * (fluid_.rho[i] - options_.rho0);
  });
}

template void BasicSphFluid<2>::save(State&) const;
template void BasicSphFluid<3>::save(State&) const;
template void BasicSphFluid<2>::restore(const State&);
template void BasicSphFluid<3>::restore(const State&);
template void BasicSphFluid<2>::write_state(StateArchive&, const std::string&) const;
template void BasicSphFluid<3>::write_state(StateArchive&, const std::string&) const;
template void BasicSphFluid<2>::read_state(const StateArchive&, const std::string&);
template void BasicSphFluid<3>::read_state(const StateArchive&, const std::string&);

} // namespace fsi::sph
