// What a scene reads off the fluid: neighbour count, kinetic energy, momentum, a pressure probe and
// the surge front.
#include "fluid_sph/sph_fluid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fsi::sph {

double SphFluid::mean_neighbours() const {
  const std::size_t n = fluid_.size();
  if (n == 0) return 0.0;
  return static_cast<double>(pstart_[n] + wstart_[n]) / static_cast<double>(n);
}

double SphFluid::kinetic_energy() const {
  double e = 0.0;
  for (std::size_t i = 0; i < fluid_.size(); ++i)
    e += fluid_.vx[i] * fluid_.vx[i] + fluid_.vy[i] * fluid_.vy[i];
  return 0.5 * mass_ * e;
}

Vec2 SphFluid::momentum() const {
  Vec2 m = Vec2::Zero();
  for (std::size_t i = 0; i < fluid_.size(); ++i) m += Vec2(fluid_.vx[i], fluid_.vy[i]);
  return mass_ * m;
}

double SphFluid::pressure_at(const Vec2& point) const {
  double sw = 0.0, swp = 0.0;
  const double c2 = options_.c0 * options_.c0;
  for (std::size_t i = 0; i < fluid_.size(); ++i) {
    double dx = point.x() - fluid_.x[i], dy = point.y() - fluid_.y[i];
    const Vec2 period = options_.domain_max - options_.domain_min;
    if (options_.periodic_x) dx -= period.x() * std::round(dx / period.x());
    if (options_.periodic_y) dy -= period.y() * std::round(dy / period.y());
    const double w = kernel_.W(std::sqrt(dx * dx + dy * dy)) * fluid_.vol[i];
    sw += w;
    swp += w * c2 * (fluid_.rho[i] - options_.rho0);
  }
  return sw > 0.0 ? swp / sw : 0.0;
}

double SphFluid::surge_front() const {
  // The largest x of the bulk, as the EMPS fluid's probe (pnd >= n0/2, pnd without i itself): a
  // particle whose neighbours' kernel sum (fluid and wall, without its own W(0), about a third
  // of sigma0) is below half the lattice's is spray, skipped. With W(0) counted, a lone particle
  // sliding on a floor would pass (0.54 sigma0: W(0) and the half-plane of dummies below it).
  const double w0 = kernel_.W(0.0), bulk = 0.5 * (sigma0_ - w0);
  double front = -std::numeric_limits<double>::max();
  for (std::size_t i = 0; i < fluid_.size(); ++i)
    if (kernel_sum(i) - w0 >= bulk) front = std::max(front, fluid_.x[i]);
  return front;
}

} // namespace fsi::sph
