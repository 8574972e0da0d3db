// Time integration: the stable step dt_s, one velocity-Verlet substep, and advance over a
// coupling step in substeps with the loads held.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "fsi/core/error.hpp"
#include "fsi/core/parallel.hpp"
#include "solid_tlsph/solid.hpp"

namespace fsi::tlsph {

template <int D> double BasicTlsphSolid<D>::stable_dt() const {
  struct Max {
    double a2, v2;
  };
  const Max m = parallel_reduce(
      size(), Max{0.0, 0.0},
      [&](std::size_t i) {
        const double v2 = velocity(i).squaredNorm();
        if (clamped_[i]) return Max{0.0, v2};
        return Max{acceleration(i).squaredNorm(), v2};
      },
      [](Max a, Max b) {
        return Max{std::max(a.a2, b.a2), std::max(a.v2, b.v2)};
      });
  const double a = std::sqrt(m.a2), v = std::sqrt(m.v2);
  double dt = h_ / (c_s_ + v);
  if (a > 0.0) dt = std::min(dt, std::sqrt(h_ / a));
  return options_.cfl * dt_scale_ * dt;
}

template <int D> void BasicTlsphSolid<D>::substep(double dt) {
  const std::size_t n = size();
  const double half = 0.5 * dt;
  // Velocity Verlet: first half kick and drift with a^n.
  parallel_for(n, [&](std::size_t i) {
    if (clamped_[i]) return;
    for (int k = 0; k < D; ++k) v_[k][i] += half * a_[k][i], x_[k][i] += dt * v_[k][i];
  });
  double work = 0.0; // f . dx of the loaded particles, in a fixed order
  for (const std::uint32_t i : loaded_) work += dt * at(f_, i).dot(velocity(i));
  ++step_;
  time_ += dt;
  prescribe(time_);
  compute_stress();
  compute_acceleration();
  // Second half kick with a^{n+1}.
  parallel_for(n, [&](std::size_t i) {
    if (clamped_[i]) return;
    for (int k = 0; k < D; ++k) v_[k][i] += half * a_[k][i];
  });
  external_work_ += work;
}

template <int D> int BasicTlsphSolid<D>::advance(double t, double dt) {
  if (!(std::abs(t - time_) <= 1e-12 * (1.0 + std::abs(t)))) {
    std::ostringstream s;
    s.precision(17);
    s << "tlsph: advance from t = " << t << " but the solid is at t = " << time_;
    throw InputError(s.str());
  }
  if (!(dt >= 0.0)) throw InputError("tlsph: advance with dt = " + std::to_string(dt) + " < 0");
  const double t_end = time_ + dt;
  int steps = 0;
  while (time_ < t_end) {
    const double remaining = t_end - time_;
    const double dts = stable_dt();
    const double k = std::ceil(remaining / dts);
    if (k <= 1.0) {
      substep(remaining);
      time_ = t_end;
    } else {
      substep(remaining / k);
    }
    ++steps;
  }
  return steps;
}

template double BasicTlsphSolid<2>::stable_dt() const;
template double BasicTlsphSolid<3>::stable_dt() const;
template void BasicTlsphSolid<2>::substep(double);
template void BasicTlsphSolid<3>::substep(double);
template int BasicTlsphSolid<2>::advance(double, double);
template int BasicTlsphSolid<3>::advance(double, double);

} // namespace fsi::tlsph
