// The run's guard after each acoustic step: finite positions and velocities, density within
// [rho_min_factor, rho_max_factor] rho0; the particle a message names.
#include "fluid_sph/sph_fluid.hpp"

#include "shared.hpp"

#include "fsi/core/error.hpp"
#include "fsi/core/parallel.hpp"

#include <algorithm>
#include <cmath>

namespace fsi::sph {

std::string SphFluid::where(std::size_t i, long step, double t) const {
  return "particle " + std::to_string(fluid_.id[i]) + " at (" + fmt(fluid_.x[i]) + ", " +
         fmt(fluid_.y[i]) + "), step " + std::to_string(step) + ", t = " + fmt(t) + " s";
}

void SphFluid::guard(long step, double t) const {
  const auto& f = fluid_;
  const double lo = options_.rho_min_factor * options_.rho0,
               hi = options_.rho_max_factor * options_.rho0;
  const std::size_t bad = parallel_reduce(
      f.size(), none,
      [&](std::size_t i) {
        const bool ok = std::isfinite(f.x[i]) && std::isfinite(f.y[i]) && std::isfinite(f.vx[i]) &&
                        std::isfinite(f.vy[i]) && f.rho[i] >= lo && f.rho[i] <= hi;
        return ok ? none : i;
      },
      [](std::size_t a, std::size_t b) { return std::min(a, b); });
  if (bad == none) return;
  const double r = f.rho[bad];
  if (std::isfinite(r) && std::isfinite(f.vx[bad]) && std::isfinite(f.vy[bad]))
    throw RunError("fluid_sph: density " + fmt(r) + " out of [" + fmt(lo) + ", " + fmt(hi) +
                   "] at " + where(bad, step, t));
  throw RunError("fluid_sph: non-finite position, velocity or density at " + where(bad, step, t));
}

} // namespace fsi::sph
