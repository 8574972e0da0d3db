// The transport-velocity shift once per advection step (eqs. 23-24; internal flows).
#include "fluid_sph/sph_fluid.hpp"

#include "shared.hpp"

#include "fsi/core/parallel.hpp"

namespace fsi::sph {

template <int D> void BasicSphFluid<D>::transport_shift() {
  auto& f = fluid_;
  const double coefficient = options_.transport_coefficient * h_ * h_;
  auto& dx = scratch_;
  dx.resize(D * owned());
  std::array<const double*, S> b;
  for (int s = 0; s < S; ++s) b[s] = f.b[s]->data();
  parallel_for(owned(), [&](std::size_t i) {
    // Delta r_i = 0.2 h^2 (-sum_j (B_i + B_j) grad W_ij V_j - sum_a 2 B_i grad W_ia V_a)
    // (eq. 24 in the reference code's sign, method notes).
    double sum[D] = {}, b_i[S];
    FSI_UNROLL for (int s = 0; s < S; ++s) b_i[s] = b[s][i];
    for (std::uint32_t k = pstart_[i]; k < pstart_[i + 1]; ++k) {
      const std::uint32_t j = pj_[k];
      double g[D], b_ij[S];
      FSI_UNROLL for (int c = 0; c < D; ++c) g[c] = pdw_[k] * f.vol[j] * pe_[c][k];
      FSI_UNROLL for (int s = 0; s < S; ++s) b_ij[s] = b_i[s] + b[s][j];
      FSI_UNROLL for (int c = 0; c < D; ++c) sum[c] += sym_row<D>(b_ij, c, g);
    }
    for (std::uint32_t k = wstart_[i]; k < wstart_[i + 1]; ++k) {
      const double vw = walls_.vol[wj_[k]];
      double g[D];
      FSI_UNROLL for (int c = 0; c < D; ++c) g[c] = wdw_[k] * vw * we_[c][k];
      FSI_UNROLL for (int c = 0; c < D; ++c) sum[c] += 2.0 * sym_row<D>(b_i, c, g);
    }
    FSI_UNROLL for (int c = 0; c < D; ++c) dx[D * i + static_cast<std::size_t>(c)] =
        -coefficient * sum[c];
  });
  parallel_for(owned(), [&](std::size_t i) {
    FSI_UNROLL for (int c = 0; c < D; ++c) f.x[c][i] += dx[D * i + static_cast<std::size_t>(c)];
  });
}

template void BasicSphFluid<2>::transport_shift();
template void BasicSphFluid<3>::transport_shift();

} // namespace fsi::sph
