// Channel inflow buffer (RKGC paper sec. 3.2, eqs. 25-26): the reference code's Turek-Hron FSI2
// set-up, a domain periodic in x whose first `buffer` metres hold the inflow profile.
#include "fluid_sph/sph_fluid.hpp"

#include "fsi/core/parallel.hpp"

#include <cmath>
#include <numbers>

namespace fsi::sph {

double Inflow::profile(double y, double t) const {
  const double H = y_max - y_min, s = y - y_min;
  if (s <= 0.0 || s >= H) return 0.0;
  // eq. 26: the mean velocity ramps up over t_s.
  const double mean = t < ramp_time
                          ? 0.5 * velocity * (1.0 - std::cos(std::numbers::pi * t / ramp_time))
                          : velocity;
  return 1.5 * mean * 4.0 * s * (H - s) / (H * H); // eq. 25, mean over the height = mean
}

template <int D> void BasicSphFluid<D>::impose_inflow(double t) requires(D == 2) {
  auto& f = fluid_;
  const Inflow& in = options_.inflow;
  const double x0 = options_.domain_min.x(), x1 = x0 + in.buffer;
  parallel_for(owned(), [&](std::size_t i) {
    const double x = grid_.wrap_x(f.x[0][i]);
    if (x < x0 || x >= x1) return;
    f.v[0][i] = in.profile(f.x[1][i], t);
    f.v[1][i] = 0.0;
  });
}

template void BasicSphFluid<2>::impose_inflow(double);

} // namespace fsi::sph
