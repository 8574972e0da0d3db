// The fluid's set-up: a lattice fill, the particles and walls of a scene, the first advection
// step's start; initial velocities and wall motions.
#include "fluid_sph/sph_fluid.hpp"

#include "shared.hpp"

#include "fsi/core/error.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace fsi::sph {

std::vector<Vec2> fill_rectangle(const Vec2& lo, const Vec2& hi, double dp) {
  std::vector<Vec2> out;
  const int nx = static_cast<int>(std::floor((hi.x() - lo.x()) / dp + 1e-9));
  const int ny = static_cast<int>(std::floor((hi.y() - lo.y()) / dp + 1e-9));
  out.reserve(static_cast<std::size_t>(std::max(nx, 0) * std::max(ny, 0)));
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) out.emplace_back(lo.x() + (i + 0.5) * dp, lo.y() + (j + 0.5) * dp);
  return out;
}

SphFluid::SphFluid(const SphOptions& options, const std::vector<Vec2>& positions,
                   const std::vector<WallPolyline>& walls, const std::vector<WallPoint>& points,
                   std::vector<WallDistance> distances)
    : options_(options), kernel_((options.validate(), options.h())), h_(options.h()), sigma0_(0.0),
      mass_(options.mass()), distances_(std::move(distances)) {
  const double dp = options_.dp;
  // sigma0: the lattice sum of W (method notes, "Kernel and resolution").
  const int reach = static_cast<int>(std::ceil(kernel_.cutoff() / dp)) + 1;
  for (int j = -reach; j <= reach; ++j)
    for (int i = -reach; i <= reach; ++i) sigma0_ += kernel_.W(dp * std::hypot(i, j));

  const Vec2& lo = options_.domain_min;
  const Vec2& hi = options_.domain_max;
  grid_ =
      particles::PeriodicGrid(lo, hi, kernel_.cutoff(), options_.periodic_x, options_.periodic_y);
  wall_grid_ = grid_;

  const std::size_t n = positions.size();
  fluid_.fields.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& r = positions[i];
    if (!(r.x() >= lo.x() && r.x() <= hi.x() && r.y() >= lo.y() && r.y() <= hi.y()))
      throw InputError("fluid_sph: particle " + std::to_string(i) + " at (" + fmt(r.x()) + ", " +
                       fmt(r.y()) + ") is outside the domain");
    fluid_.id[i] = static_cast<std::uint32_t>(i);
    fluid_.x[i] = r.x();
    fluid_.y[i] = r.y();
    fluid_.rho[i] = options_.rho0;
    fluid_.vol[i] = dp * dp;
    fluid_.b00[i] = fluid_.b11[i] = 1.0;
    fluid_.apx[i] = fluid_.ax[i] = options_.gravity.x();
    fluid_.apy[i] = fluid_.ay[i] = options_.gravity.y();
  }
  fill_walls(walls);
  append_wall_points(points);
  // The first advection step starts here: its per-Dt work runs as at the end of any other.
  builds_ = -1;
  per_advection_step();
}

void SphFluid::set_velocities(const std::vector<Vec2>& v) {
  if (v.size() != fluid_.size() || removed_ > 0)
    throw InputError("fluid_sph: " + std::to_string(v.size()) + " initial velocities for " +
                     std::to_string(fluid_.size()) + " particles");
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Vec2& w = v[fluid_.id[i]];
    fluid_.vx[i] = w.x(), fluid_.vy[i] = w.y();
  }
  // The viscous force and Dt depend on the velocities: redo this advection step's start.
  prior_acceleration();
  compute_advection_dt();
  if (options_.fixed_dt > 0.0) {
    subs_ = std::max(1L, static_cast<long>(std::floor(Dt_ / options_.fixed_dt)));
    Dt_ = static_cast<double>(subs_) * options_.fixed_dt;
  }
  compute_acoustic_dt();
}

void SphFluid::set_wall_motion(int group, WallMotion motion) {
  if (group < 0) throw InputError("fluid_sph: wall group " + std::to_string(group) + " < 0");
  if (motions_.size() <= static_cast<std::size_t>(group))
    motions_.resize(static_cast<std::size_t>(group) + 1);
  motions_[static_cast<std::size_t>(group)] = std::move(motion);
}

} // namespace fsi::sph
