// Dual-criteria time stepping (method notes, "Fluid step"): acoustic steps dt within an
// advection step Dt, and the per-Dt work (wrap, sort, pairs, density, B, prior acceleration,
// transport shift) at the end of each.
#include "fluid_sph/sph_fluid.hpp"

#include "shared.hpp"

#include "fsi/core/error.hpp"
#include "fsi/core/parallel.hpp"

#include <algorithm>
#include <cmath>

namespace fsi::sph {

template <int D> double BasicSphFluid<D>::next_dt() const {
  if (options_.fixed_dt > 0.0) return options_.fixed_dt;
  return std::min(dt_acoustic_, Dt_ - elapsed_);
}

template <int D> void BasicSphFluid<D>::advance(double dt) {
  const double left = Dt_ - elapsed_;
  if (!(dt > 0.0) || (options_.fixed_dt <= 0.0 && dt > left * (1.0 + 1e-12)))
    throw InputError("fluid_sph: acoustic step " + fmt(dt) + " not in (0, " + fmt(left) +
                     "] (what is left of the advection step)");
  if constexpr (D == 2) move_walls(dt);
  first_half(dt);
  if (tracked_ < walls_.size()) wall_reaction();
  second_half(dt);
  if constexpr (D == 2)
    if (options_.inflow.on()) impose_inflow(t_ + dt);
  if (options_.damping_time > 0.0 && t_ < options_.damping_time) {
    const double T = options_.damping_time;
    const double keep = std::max(0.0, 1.0 - dt * 20.0 / T * (1.0 - t_ / T));
    parallel_for(owned(), [&](std::size_t i) {
      for (int c = 0; c < D; ++c) fluid_.v[c][i] *= keep;
    });
  }
  t_ += dt;
  ++step_;
  elapsed_ += dt;
  guard(step_, t_);
  const bool filled = options_.fixed_dt > 0.0 ? ++sub_ >= subs_ : dt >= left * (1.0 - 1e-12);
  if (filled) per_advection_step();
}

template <int D> void BasicSphFluid<D>::advance_to(double t_end) {
  while (t_ < t_end - 1e-12 * std::max(1.0, std::abs(t_end))) {
    double dt = next_dt();
    if (options_.fixed_dt <= 0.0) dt = std::min(dt, t_end - t_);
    advance(dt);
  }
}

template <int D> void BasicSphFluid<D>::per_advection_step() {
  auto& f = fluid_;
  compute_advection_dt();
  // Periodic wrap; particles that left a non-periodic side of the domain are removed.
  hook().drop_ghosts(f.fields); // the owned particles are removed, moved and reordered
  const Vec lo = options_.domain_min, hi = options_.domain_max;
  const std::array<bool, D> periodic = options_.periodic();
  keep_.assign(f.size(), 1);
  bool any_out = false;
  for (std::size_t i = 0; i < f.size(); ++i) {
    bool out = false;
    for (int c = 0; c < D; ++c) {
      const double x = f.x[c][i] = grid_.wrap(c, f.x[c][i]);
      out = out || (!periodic[static_cast<std::size_t>(c)] && (x < lo[c] || x > hi[c]));
    }
    if (out) keep_[i] = 0, any_out = true;
  }
  if (any_out) removed_ += f.fields.compact(keep_);
  hook().migrate(f.fields, f.x, nullptr); // decomposed: to the ranks whose regions hold them now
  // Sort by cell (particles of a cell contiguous, neighbours close in memory).
  grid_.bin(f.x.coords(), f.size());
  f.fields.permute(grid_.order(), scratch_);
  for (int c = 0; c < D; ++c) {
    std::copy(f.x[c].begin(), f.x[c].end(), f.xb[c].begin());
    std::copy(walls_.x[c].begin(), walls_.x[c].end(), walls_.xb[c].begin());
  }
  build_ghosts(f.x);
  build_pairs();
  ++builds_;
  reinitialise_density();
  hook().update_ghosts(f.fields, particles::FieldList(f.vol)); // V_j for A (eq. 19)
  correction_matrices();
  particles::FieldList b;
  for (const auto* b_s : f.b) b.add(*b_s);
  hook().update_ghosts(f.fields, b); // B_j for the pair sums (eqs. 18, 20, 24)
  prior_acceleration();
  if (options_.transport_velocity) transport_shift();
  elapsed_ = 0.0;
  sub_ = 0;
  if (options_.fixed_dt > 0.0) {
    subs_ = std::max(1L, static_cast<long>(std::floor(Dt_ / options_.fixed_dt)));
    Dt_ = static_cast<double>(subs_) * options_.fixed_dt;
  }
  if (dt_acoustic_ <= 0.0) compute_acoustic_dt();
}

template <int D> void BasicSphFluid<D>::compute_acoustic_dt() {
  const auto& f = fluid_;
  double worst = options_.c0;
  for (std::size_t i = 0; i < owned(); ++i) {
    double v_i[D], a_i[D];
    for (int c = 0; c < D; ++c) v_i[c] = f.v[c][i], a_i[c] = f.a[c][i];
    const double v = length<D>(v_i), a = length<D>(a_i);
    worst = std::max(worst, std::max(options_.c0 + v, std::sqrt(4.0 * h_ * a)));
  }
  dt_acoustic_ = options_.acoustic_cfl * h_ / hook().max(worst);
}

template <int D> void BasicSphFluid<D>::compute_advection_dt() {
  const auto& f = fluid_;
  const double four_h = 4.0 * h_;
  // Dt = 0.25 h / max(sqrt(max(|v|^2, 4 h |a|)), U_ref, nu / h) (method notes).
  const double worst = hook().max(parallel_reduce(
      owned(), 0.0,
      [&](std::size_t i) {
        double v_i[D], a_i[D];
        for (int c = 0; c < D; ++c) v_i[c] = f.v[c][i], a_i[c] = f.a[c][i];
        return std::max(dot<D>(v_i, v_i), four_h * std::sqrt(dot<D>(a_i, a_i)));
      },
      [](double l, double r) { return std::max(l, r); }));
  const double speed =
      std::max({std::sqrt(worst), options_.u_advection(), options_.viscosity / h_});
  Dt_ = options_.advection_cfl * h_ / speed;
  // The viscous term is frozen over Dt (explicit): its diffusion number nu Dt / h^2 stays below
  // viscous_number (the Taylor-Green decay gains 5 % at 0.19, docs/fluid_sph.md).
  const double nu = options_.viscosity, number = options_.viscous_number;
  if (nu > 0.0 && number > 0.0) Dt_ = std::min(Dt_, number * h_ * h_ / nu);
}

template <int D> void BasicSphFluid<D>::build_ghosts(const particles::VectorField<D>& x) {
  hook().build_ghosts(fluid_.fields, x, kernel_.cutoff()); // the pairs' reach: no skin
}

template <int D> void BasicSphFluid<D>::decompose(particles::Decomposition<D>& decomposition) {
  if (options_.periodic_x || options_.periodic_y || options_.periodic_z)
    throw InputError("fluid_sph: a periodic fluid cannot be decomposed");
  decomposition_ = &decomposition;
  if (builds_ < 0) return per_advection_step(); // a deferred block: the first step's start
  // The whole fluid (built whole, or a checkpoint): this rank's block of it. The tracked walls'
  // viscous force of this Dt was summed over every particle on every rank: rank 0 keeps it, so
  // the ranks' parts sum to it.
  particles::keep_block(fluid_.fields, hook().rank(), hook().processes(), keep_);
  if (tracked_ < walls_.size() && hook().rank() != 0)
    for (int c = 0; c < D; ++c)
      std::fill(walls_.fv[c].begin() + static_cast<std::ptrdiff_t>(tracked_), walls_.fv[c].end(),
                0.0);
  // The advection step under way: partitioned at its build positions, its pairs rebuilt there
  // (B, V, rho and the prior acceleration are the particles' own, moved with them). Unit loads
  // (no work): the walls are particles, so a particle by a wall has wall neighbours where a bulk
  // one has fluid ones (not counted: docs/performance.md "Cost weights").
  hook().migrate(fluid_.fields, fluid_.xb, nullptr);
  build_ghosts(fluid_.xb);
  build_pairs(false);
}

template double BasicSphFluid<2>::next_dt() const;
template double BasicSphFluid<3>::next_dt() const;
template void BasicSphFluid<2>::advance(double);
template void BasicSphFluid<3>::advance(double);
template void BasicSphFluid<2>::advance_to(double);
template void BasicSphFluid<3>::advance_to(double);
template void BasicSphFluid<2>::per_advection_step();
template void BasicSphFluid<3>::per_advection_step();
template void BasicSphFluid<2>::compute_acoustic_dt();
template void BasicSphFluid<3>::compute_acoustic_dt();
template void BasicSphFluid<2>::compute_advection_dt();
template void BasicSphFluid<3>::compute_advection_dt();
template void BasicSphFluid<2>::build_ghosts(const particles::VectorField<2>&);
template void BasicSphFluid<3>::build_ghosts(const particles::VectorField<3>&);
template void BasicSphFluid<2>::decompose(particles::Decomposition<2>&);
template void BasicSphFluid<3>::decompose(particles::Decomposition<3>&);

} // namespace fsi::sph
