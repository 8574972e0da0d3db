// What a scene reads off the fluid: neighbour count, kinetic energy, momentum, a pressure probe and
// the surge front.
#include "fluid_sph/sph_fluid.hpp"

#include "shared.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fsi::sph {

template <int D> double BasicSphFluid<D>::mean_neighbours() const {
  const std::size_t n = owned();
  const double pairs = hook().sum(static_cast<double>(pstart_[n] + wstart_[n]));
  const double all = hook().sum(static_cast<double>(n));
  return all > 0.0 ? pairs / all : 0.0;
}

template <int D> double BasicSphFluid<D>::kinetic_energy() const {
  double e = 0.0;
  for (std::size_t i = 0; i < owned(); ++i) {
    double v[D];
    for (int c = 0; c < D; ++c) v[c] = fluid_.v[c][i];
    e += dot<D>(v, v);
  }
  return 0.5 * mass_ * hook().sum(e);
}

template <int D> auto BasicSphFluid<D>::momentum() const -> Vec {
  Vec m = Vec::Zero();
  for (std::size_t i = 0; i < owned(); ++i) {
    Vec v;
    for (int c = 0; c < D; ++c) v[c] = fluid_.v[c][i];
    m += v;
  }
  for (int c = 0; c < D; ++c) m[c] = hook().sum(m[c]);
  return mass_ * m;
}

template <int D>
template <class Value>
double BasicSphFluid<D>::shepard(const Vec& point, Value value) const {
  double sw = 0.0, swv = 0.0;
  const Vec period = options_.domain_max - options_.domain_min;
  const std::array<bool, D> periodic = options_.periodic();
  for (std::size_t i = 0; i < owned(); ++i) {
    double d[D];
    for (int c = 0; c < D; ++c) {
      d[c] = point[c] - fluid_.x[c][i];
      if (periodic[static_cast<std::size_t>(c)]) d[c] -= period[c] * std::round(d[c] / period[c]);
    }
    const double w = kernel_.W(std::sqrt(dot<D>(d, d))) * fluid_.vol[i];
    sw += w;
    swv += w * value(i);
  }
  sw = hook().sum(sw), swv = hook().sum(swv);
  return sw > 0.0 ? swv / sw : 0.0;
}

template <int D> double BasicSphFluid<D>::pressure_at(const Vec& point) const {
  const double c2 = options_.c0 * options_.c0;
  return shepard(point, [&](std::size_t i) { return c2 * (fluid_.rho[i] - options_.rho0); });
}

template <int D> auto BasicSphFluid<D>::velocity_at(const Vec& point) const -> Vec {
  Vec v;
  for (int c = 0; c < D; ++c) v[c] = shepard(point, [&](std::size_t i) { return fluid_.v[c][i]; });
  return v;
}

template <int D> double BasicSphFluid<D>::surge_front() const {
  // The largest x of the bulk, as the EMPS fluid's probe (pnd >= n0/2, pnd without i itself): a
  // particle whose neighbours' kernel sum (fluid and wall, without its own W(0), about a third
  // of sigma0) is below half the lattice's is spray, skipped. With W(0) counted, a lone particle
  // sliding on a floor would pass (0.54 sigma0: W(0) and the half-plane of dummies below it).
  const double w0 = kernel_.W(0.0), bulk = 0.5 * (sigma0_ - w0);
  double front = -std::numeric_limits<double>::max();
  for (std::size_t i = 0; i < owned(); ++i)
    if (kernel_sum(i) - w0 >= bulk) front = std::max(front, fluid_.x[0][i]);
  return hook().max(front);
}

template double BasicSphFluid<2>::mean_neighbours() const;
template double BasicSphFluid<3>::mean_neighbours() const;
template double BasicSphFluid<2>::kinetic_energy() const;
template double BasicSphFluid<3>::kinetic_energy() const;
template auto BasicSphFluid<2>::momentum() const -> Vec;
template auto BasicSphFluid<3>::momentum() const -> Vec;
template double BasicSphFluid<2>::pressure_at(const Vec&) const;
template double BasicSphFluid<3>::pressure_at(const Vec&) const;
template auto BasicSphFluid<2>::velocity_at(const Vec&) const -> Vec;
template auto BasicSphFluid<3>::velocity_at(const Vec&) const -> Vec;
template double BasicSphFluid<2>::surge_front() const;
template double BasicSphFluid<3>::surge_front() const;

} // namespace fsi::sph
