// The fluid's set-up: lattice fills, the particles and walls of a scene, the first advection
// step's start; initial velocities and wall motions.
#include "fluid_sph/sph_fluid.hpp"

#include "shared.hpp"

#include "fsi/core/error.hpp"
#include "particles/lattice.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace fsi::sph {

std::vector<Vec2> fill_rectangle(const Vec2& lo, const Vec2& hi, double dp) {
  return particles::lattice_box<2>(lo, hi, dp);
}

template <int D>
BasicSphFluid<D>::BasicSphFluid(Setup, const Options& options, const std::vector<Vec>& positions,
                                std::vector<Distance> distances, std::size_t first_id)
    : options_(options), kernel_((options.validate(), options.h())), h_(options.h()), sigma0_(0.0),
      mass_(options.mass()), distances_(std::move(distances)) {
  const double dp = options_.dp;
  // sigma0: the lattice sum of W (method notes, "Kernel and resolution").
  const int reach = static_cast<int>(std::ceil(kernel_.cutoff() / dp)) + 1;
  if constexpr (D == 2) {
    for (int j = -reach; j <= reach; ++j)
      for (int i = -reach; i <= reach; ++i) sigma0_ += kernel_.W(dp * std::hypot(i, j));
  } else {
    for (int k = -reach; k <= reach; ++k)
      for (int j = -reach; j <= reach; ++j)
        for (int i = -reach; i <= reach; ++i) sigma0_ += kernel_.W(dp * std::hypot(i, j, k));
  }

  const Vec& lo = options_.domain_min;
  const Vec& hi = options_.domain_max;
  grid_ = particles::BasicPeriodicGrid<D>(lo, hi, kernel_.cutoff(), options_.periodic());
  wall_grid_ = grid_;

  const std::size_t n = positions.size();
  fluid_.fields.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec& r = positions[i];
    if (!((r.array() >= lo.array()).all() && (r.array() <= hi.array()).all())) {
      std::string at = fmt(r[0]);
      for (int c = 1; c < D; ++c) at += ", " + fmt(r[c]);
      throw InputError("fluid_sph: particle " + std::to_string(first_id + i) + " at (" + at +
                       ") is outside the domain");
    }
    fluid_.id[i] = static_cast<std::uint32_t>(first_id + i);
    for (int c = 0; c < D; ++c) {
      fluid_.x[c][i] = r[c];
      fluid_.ap[c][i] = fluid_.a[c][i] = options_.gravity[c];
    }
    fluid_.rho[i] = options_.rho0;
    fluid_.vol[i] = options_.cell_volume();
    for (int c = 0; c < D; ++c) (*fluid_.b[sym<D>(c, c)])[i] = 1.0;
  }
}

template <int D>
BasicSphFluid<D>::BasicSphFluid(const Options& options, const std::vector<Vec>& positions,
                                const std::vector<WallPolyline>& walls,
                                const std::vector<Point>& points, std::vector<Distance> distances,
                                const particles::SetupBlock& block) requires(D == 2)
    : BasicSphFluid(Setup{}, options, positions, std::move(distances), block.first) {
  fill_walls(walls);
  append_wall_points(points);
  start(block);
}

template <int D>
BasicSphFluid<D>::BasicSphFluid(const Options& options, const std::vector<Vec>& positions,
                                const std::vector<Point>& points, std::vector<Distance> distances,
                                const particles::SetupBlock& block) requires(D == 3)
    : BasicSphFluid(Setup{}, options, positions, std::move(distances), block.first) {
  append_wall_points(points);
  start(block);
}

// The first advection step starts with its per-Dt work, as at the end of any other (builds_ -1
// until then: decompose() starts a deferred block).
template <int D> void BasicSphFluid<D>::start(const particles::SetupBlock& block) {
  builds_ = -1;
  if (!block.deferred) per_advection_step();
}

template <int D> void BasicSphFluid<D>::set_velocities(const std::vector<Vec>& v) {
  if (v.size() != fluid_.size() || removed_ > 0)
    throw InputError("fluid_sph: " + std::to_string(v.size()) + " initial velocities for " +
                     std::to_string(fluid_.size()) + " particles");
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Vec& w = v[fluid_.id[i]];
    for (int c = 0; c < D; ++c) fluid_.v[c][i] = w[c];
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

template <int D>
void BasicSphFluid<D>::set_wall_motion(int group, WallMotion motion) requires(D == 2) {
  if (group < 0) throw InputError("fluid_sph: wall group " + std::to_string(group) + " < 0");
  if (motions_.size() <= static_cast<std::size_t>(group))
    motions_.resize(static_cast<std::size_t>(group) + 1);
  motions_[static_cast<std::size_t>(group)] = std::move(motion);
}

// Member by member (an explicit instantiation of the class would take the other dimension's
// constructor too, clang 14).
template BasicSphFluid<2>::BasicSphFluid(Setup, const Options&, const std::vector<Vec>&,
                                         std::vector<Distance>, std::size_t);
template BasicSphFluid<3>::BasicSphFluid(Setup, const Options&, const std::vector<Vec>&,
                                         std::vector<Distance>, std::size_t);
template BasicSphFluid<2>::BasicSphFluid(const Options&, const std::vector<Vec>&,
                                         const std::vector<WallPolyline>&,
                                         const std::vector<Point>&, std::vector<Distance>,
                                         const particles::SetupBlock&);
template BasicSphFluid<3>::BasicSphFluid(const Options&, const std::vector<Vec>&,
                                         const std::vector<Point>&, std::vector<Distance>,
                                         const particles::SetupBlock&);
template void BasicSphFluid<2>::start(const particles::SetupBlock&);
template void BasicSphFluid<3>::start(const particles::SetupBlock&);
template void BasicSphFluid<2>::set_velocities(const std::vector<Vec>&);
template void BasicSphFluid<3>::set_velocities(const std::vector<Vec>&);
template void BasicSphFluid<2>::set_wall_motion(int, WallMotion);

} // namespace fsi::sph
