// Wall particles given directly (a structure's boundary points) and the fluid's force on them:
// the reaction of the wall terms of eqs. 15-17 and of the no-slip viscous term, so that the
// momentum the fluid gains from them is exactly what they lose (action = -reaction).
#include "fluid_sph/sph_fluid.hpp"

#include "wall_terms.hpp"

#include "fsi/core/error.hpp"

#include <algorithm>
#include <cmath>

namespace fsi::sph {

template <int D> void BasicSphFluid<D>::append_wall_points(const std::vector<Point>& points) {
  const std::size_t first = walls_.size();
  walls_.fields.resize(first + points.size());
  for (std::size_t k = 0; k < points.size(); ++k) {
    const Point& q = points[k];
    if (q.group < 0) throw InputError("fluid_sph: wall group " + std::to_string(q.group) + " < 0");
    if (!(std::abs(q.n.norm() - 1.0) < 1e-9))
      throw InputError("fluid_sph: wall point " + std::to_string(k) + " has no unit normal");
    if (!(q.depth >= 0.0 && q.corner >= 0.0 && q.corner < 1.0 && q.vol >= 0.0))
      throw InputError("fluid_sph: wall point " + std::to_string(k) +
                       " has a depth < 0, a corner outside [0, 1) or a volume < 0");
    const std::size_t a = first + k;
    walls_.group[a] = static_cast<std::uint32_t>(q.group);
    for (int c = 0; c < D; ++c) {
      walls_.x[c][a] = walls_.x0[c][a] = walls_.xb[c][a] = q.x[c];
      walls_.n[c][a] = walls_.n0[c][a] = q.n[c];
    }
    walls_.depth[a] = q.depth;
    walls_.corner[a] = q.corner;
    walls_.vol[a] = q.vol > 0.0 ? q.vol : options_.cell_volume();
  }
}

template void BasicSphFluid<2>::append_wall_points(const std::vector<Point>&);
template void BasicSphFluid<3>::append_wall_points(const std::vector<Point>&);

template <int D> void BasicSphFluid<D>::track_wall_forces(std::size_t first, Reaction reaction) {
  if (first > walls_.size())
    throw InputError("fluid_sph: tracked walls from " + std::to_string(first) + " of " +
                     std::to_string(walls_.size()));
  tracked_ = first;
  reaction_ = reaction;
  for (auto& w : wf_) w.assign(walls_.size() - first, 0.0);
  if (builds_ >= 0) wall_viscous_reaction(); // for the current advection step (if started)
}

template void BasicSphFluid<2>::track_wall_forces(std::size_t, Reaction);
template void BasicSphFluid<3>::track_wall_forces(std::size_t, Reaction);

// The wall terms of first_half for each pair (i, a) with a tracked, times -V_i: the force on a,
// plus the viscous force of this advection step (kept in fv). Reaction::reference_code
// takes B_i = I in the pressure part (the reference code's reaction, method notes).
// Sequential scatter over the owned fluid particles (deterministic for any thread count;
// decomposed, each rank's part of the force: the caller sums them over the ranks).
template <int D> void BasicSphFluid<D>::wall_reaction() {
  const auto& f = fluid_;
  const double rho0c0 = options_.rho0 * options_.c0, inv_c0 = 1.0 / options_.c0;
  // The viscous part of this step is that of the prior acceleration the fluid felt (this Dt's).
  for (int c = 0; c < D; ++c)
    std::copy(walls_.fv[c].begin() + static_cast<std::ptrdiff_t>(tracked_), walls_.fv[c].end(),
              wf_[c].begin());
  const bool exact = reaction_ == Reaction::exact;
  for (std::size_t i = 0; i < owned(); ++i) {
    const double p_i = f.p[i], rho_i = f.rho[i], V_i = f.vol[i];
    double b_i[S];
    for (int r = 0; r < D; ++r)
      for (int c = r; c < D; ++c) b_i[sym<D>(r, c)] = exact ? (*f.b[sym<D>(r, c)])[i] : r == c;
    for (std::uint32_t k = wstart_[i]; k < wstart_[i + 1]; ++k) {
      const std::uint32_t a = wj_[k];
      if (a < tracked_) continue;
      WallPair<D> q{p_i, rho_i, wr_[k], {},     {},     wdw_[k] * walls_.vol[a],
                    b_i, {},    {},     rho0c0, inv_c0, options_.riemann_limiter};
      for (int c = 0; c < D; ++c) {
        q.da[c] = f.ap[c][i] - walls_.a[c][a], q.e[c] = we_[c][k];
        q.dv[c] = f.v[c][i] - walls_.v[c][a], q.n[c] = walls_.n[c][a];
      }
      const auto t = wall_term(q);
      for (int c = 0; c < D; ++c) wf_[c][a - tracked_] -= V_i * t[c];
    }
  }
}

template void BasicSphFluid<2>::wall_reaction();
template void BasicSphFluid<3>::wall_reaction();

// The no-slip wall term of prior_acceleration, 2 mu V_i 2 (v_i - v_a) dW V_a / (r + 0.01 h) on
// i, reversed on a; frozen over the advection step like the fluid's prior acceleration.
template <int D> void BasicSphFluid<D>::wall_viscous_reaction() {
  const auto& f = fluid_;
  const double mu = options_.rho0 * options_.viscosity, reg = 0.01 * h_;
  for (std::size_t a = tracked_; a < walls_.size(); ++a)
    for (int c = 0; c < D; ++c) walls_.fv[c][a] = 0.0;
  if (!(mu > 0.0)) return;
  for (std::size_t i = 0; i < owned(); ++i) {
    const double c = 2.0 * mu * f.vol[i];
    for (std::uint32_t k = wstart_[i]; k < wstart_[i + 1]; ++k) {
      const std::uint32_t a = wj_[k];
      if (a < tracked_) continue;
      const double s = c * wall_viscous_weight(wdw_[k], walls_.vol[a], wr_[k], reg);
      for (int c = 0; c < D; ++c) walls_.fv[c][a] -= (f.v[c][i] - walls_.v[c][a]) * s;
    }
  }
}

template void BasicSphFluid<2>::wall_viscous_reaction();
template void BasicSphFluid<3>::wall_viscous_reaction();

template <int D> auto BasicSphFluid<D>::wall_force(std::size_t a) const -> Vec {
  Vec force;
  for (int c = 0; c < D; ++c) force[c] = wf_[c][a - tracked_];
  return force;
}

template auto BasicSphFluid<2>::wall_force(std::size_t) const -> Vec;
template auto BasicSphFluid<3>::wall_force(std::size_t) const -> Vec;

} // namespace fsi::sph
