// The transport-velocity shift once per advection step (eqs. 23-24; internal flows).
#include "fluid_sph/sph_fluid.hpp"

#include "fsi/core/parallel.hpp"

namespace fsi::sph {

void SphFluid::transport_shift() {
  auto& f = fluid_;
  const double c = options_.transport_coefficient * h_ * h_;
  auto& dx = scratch_;
  dx.resize(2 * f.size());
  parallel_for(f.size(), [&](std::size_t i) {
    // Delta r_i = 0.2 h^2 (-sum_j (B_i + B_j) grad W_ij V_j - sum_a 2 B_i grad W_ia V_a)
    // (eq. 24 in the reference code's sign, method notes).
    double sx = 0.0, sy = 0.0;
    const double b00 = f.b00[i], b01 = f.b01[i], b11 = f.b11[i];
    for (std::uint32_t k = pstart_[i]; k < pstart_[i + 1]; ++k) {
      const std::uint32_t j = pj_[k];
      const double gx = pdw_[k] * f.vol[j] * pex_[k], gy = pdw_[k] * f.vol[j] * pey_[k];
      sx += (b00 + f.b00[j]) * gx + (b01 + f.b01[j]) * gy;
      sy += (b01 + f.b01[j]) * gx + (b11 + f.b11[j]) * gy;
    }
    for (std::uint32_t k = wstart_[i]; k < wstart_[i + 1]; ++k) {
      const double vw = walls_.vol[wj_[k]];
      const double gx = wdw_[k] * vw * wex_[k], gy = wdw_[k] * vw * wey_[k];
      sx += 2.0 * (b00 * gx + b01 * gy);
      sy += 2.0 * (b01 * gx + b11 * gy);
    }
    dx[2 * i] = -c * sx;
    dx[2 * i + 1] = -c * sy;
  });
  parallel_for(f.size(), [&](std::size_t i) {
    f.x[i] += dx[2 * i];
    f.y[i] += dx[2 * i + 1];
  });
}

} // namespace fsi::sph
