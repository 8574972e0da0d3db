// Wall particles given directly (a structure's boundary points) and the fluid's force on them:
// the reaction of the wall terms of eqs. 15-17 and of the no-slip viscous term, so that the
// momentum the fluid gains from them is exactly what they lose (action = -reaction).
#include "fluid_sph/sph_fluid.hpp"

#include "wall_terms.hpp"

#include "fsi/core/error.hpp"

#include <algorithm>
#include <cmath>

namespace fsi::sph {

void SphFluid::append_wall_points(const std::vector<WallPoint>& points) {
  const std::size_t first = walls_.size();
  walls_.fields.resize(first + points.size());
  for (std::size_t k = 0; k < points.size(); ++k) {
    const WallPoint& q = points[k];
    if (q.group < 0) throw InputError("fluid_sph: wall group " + std::to_string(q.group) + " < 0");
    if (!(std::abs(q.n.norm() - 1.0) < 1e-9))
      throw InputError("fluid_sph: wall point " + std::to_string(k) + " has no unit normal");
    if (!(q.depth >= 0.0 && q.corner >= 0.0 && q.corner < 1.0 && q.vol >= 0.0))
      throw InputError("fluid_sph: wall point " + std::to_string(k) +
                       " has a depth < 0, a corner outside [0, 1) or a volume < 0");
    const std::size_t a = first + k;
    walls_.group[a] = static_cast<std::uint32_t>(q.group);
    walls_.x[a] = walls_.x0[a] = walls_.xb[a] = q.x.x();
    walls_.y[a] = walls_.y0[a] = walls_.yb[a] = q.x.y();
    walls_.nx[a] = walls_.nx0[a] = q.n.x();
    walls_.ny[a] = walls_.ny0[a] = q.n.y();
    walls_.depth[a] = q.depth;
    walls_.corner[a] = q.corner;
    walls_.vol[a] = q.vol > 0.0 ? q.vol : options_.dp * options_.dp;
  }
}

void SphFluid::track_wall_forces(std::size_t first, Reaction reaction) {
  if (first > walls_.size())
    throw InputError("fluid_sph: tracked walls from " + std::to_string(first) + " of " +
                     std::to_string(walls_.size()));
  tracked_ = first;
  reaction_ = reaction;
  wfx_.assign(walls_.size() - first, 0.0);
  wfy_.assign(walls_.size() - first, 0.0);
  wall_viscous_reaction(); // for the current advection step
}

// The wall terms of first_half for each pair (i, a) with a tracked, times -V_i: the force on a,
// plus the viscous force of this advection step (kept in fvx, fvy). Reaction::reference_code
// takes B_i = I in the pressure part (the reference code's reaction, method notes).
// Sequential scatter over the fluid particles (deterministic for any thread count).
void SphFluid::wall_reaction() {
  const auto& f = fluid_;
  const double rho0c0 = options_.rho0 * options_.c0, inv_c0 = 1.0 / options_.c0;
  // The viscous part of this step is that of the prior acceleration the fluid felt (this Dt's).
  std::copy(walls_.fvx.begin() + static_cast<std::ptrdiff_t>(tracked_), walls_.fvx.end(),
            wfx_.begin());
  std::copy(walls_.fvy.begin() + static_cast<std::ptrdiff_t>(tracked_), walls_.fvy.end(),
            wfy_.begin());
  const bool exact = reaction_ == Reaction::exact;
  for (std::size_t i = 0; i < f.size(); ++i) {
    const double p_i = f.p[i], vx_i = f.vx[i], vy_i = f.vy[i], rho_i = f.rho[i];
    const double b00 = exact ? f.b00[i] : 1.0, b01 = exact ? f.b01[i] : 0.0;
    const double b11 = exact ? f.b11[i] : 1.0, V_i = f.vol[i];
    for (std::uint32_t k = wstart_[i]; k < wstart_[i + 1]; ++k) {
      const std::uint32_t a = wj_[k];
      if (a < tracked_) continue;
      const Vec2 t = wall_term(
          {p_i, rho_i, wr_[k], f.apx[i] - walls_.ax[a], f.apy[i] - walls_.ay[a], wex_[k], wey_[k],
           wdw_[k] * walls_.vol[a], b00, b01, b11, vx_i - walls_.vx[a], vy_i - walls_.vy[a],
           walls_.nx[a], walls_.ny[a], rho0c0, inv_c0, options_.riemann_limiter});
      wfx_[a - tracked_] -= V_i * t.x();
      wfy_[a - tracked_] -= V_i * t.y();
    }
  }
}

// The no-slip wall term of prior_acceleration, 2 mu V_i 2 (v_i - v_a) dW V_a / (r + 0.01 h) on
// i, reversed on a; frozen over the advection step like the fluid's prior acceleration.
void SphFluid::wall_viscous_reaction() {
  const auto& f = fluid_;
  const double mu = options_.rho0 * options_.viscosity, reg = 0.01 * h_;
  for (std::size_t a = tracked_; a < walls_.size(); ++a) walls_.fvx[a] = walls_.fvy[a] = 0.0;
  if (!(mu > 0.0)) return;
  for (std::size_t i = 0; i < f.size(); ++i) {
    const double c = 2.0 * mu * f.vol[i];
    for (std::uint32_t k = wstart_[i]; k < wstart_[i + 1]; ++k) {
      const std::uint32_t a = wj_[k];
      if (a < tracked_) continue;
      const double s = c * wall_viscous_weight(wdw_[k], walls_.vol[a], wr_[k], reg);
      walls_.fvx[a] -= (f.vx[i] - walls_.vx[a]) * s;
      walls_.fvy[a] -= (f.vy[i] - walls_.vy[a]) * s;
    }
  }
}

} // namespace fsi::sph
