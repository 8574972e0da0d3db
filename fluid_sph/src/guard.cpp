// The run's guard after each acoustic step: finite positions and velocities, density within
// [rho_min_factor, rho_max_factor] rho0; the particle a message names.
#include "fluid_sph/sph_fluid.hpp"

#include "shared.hpp"

#include "fsi/core/error.hpp"
#include "fsi/core/parallel.hpp"

#include <algorithm>
#include <cmath>

namespace fsi::sph {

template <int D> std::string BasicSphFluid<D>::where(std::size_t i, long step, double t) const {
  std::string at = fmt(fluid_.x[0][i]);
  for (int c = 1; c < D; ++c) at += ", " + fmt(fluid_.x[c][i]);
  return "particle " + std::to_string(fluid_.id[i]) + " at (" + at + "), step " +
         std::to_string(step) + ", t = " + fmt(t) + " s";
}

template <int D> void BasicSphFluid<D>::guard(long step, double t) const {
  const auto& f = fluid_;
  const double lo = options_.rho_min_factor * options_.rho0,
               hi = options_.rho_max_factor * options_.rho0;
  const auto finite_velocity = [&](std::size_t i) {
    for (int c = 0; c < D; ++c)
      if (!std::isfinite(f.v[c][i])) return false;
    return true;
  };
  const std::size_t bad = parallel_reduce(
      owned(), none,
      [&](std::size_t i) {
        for (int c = 0; c < D; ++c)
          if (!std::isfinite(f.x[c][i])) return i;
        const bool ok = finite_velocity(i) && f.rho[i] >= lo && f.rho[i] <= hi;
        return ok ? none : i;
      },
      [](std::size_t a, std::size_t b) { return std::min(a, b); });
  if (bad != none) { // decomposed: every process throws at agree()
    const double r = f.rho[bad];
    if (std::isfinite(r) && finite_velocity(bad))
      hook().fail("fluid_sph: density " + fmt(r) + " out of [" + fmt(lo) + ", " + fmt(hi) +
                  "] at " + where(bad, step, t));
    else
      hook().fail("fluid_sph: non-finite position, velocity or density at " + where(bad, step, t));
  }
  hook().agree();
}

template std::string BasicSphFluid<2>::where(std::size_t, long, double) const;
template std::string BasicSphFluid<3>::where(std::size_t, long, double) const;
template void BasicSphFluid<2>::guard(long, double) const;
template void BasicSphFluid<3>::guard(long, double) const;

} // namespace fsi::sph
