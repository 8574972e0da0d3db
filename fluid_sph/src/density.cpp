// Density re-initialisation once per advection step: rho_i = rho0 sigma_i / sigma0, the kernel
// sum over fluid and wall particles (method notes, "Kernel and resolution").
#include "fluid_sph/sph_fluid.hpp"

#include "fsi/core/parallel.hpp"

#include <algorithm>

namespace fsi::sph {

double SphFluid::kernel_sum(std::size_t i) const {
  double sigma = kernel_.W(0.0);
  for (std::uint32_t k = pstart_[i]; k < pstart_[i + 1]; ++k) sigma += kernel_.W(pr_[k]);
  // A wall particle counts as V_a / dp^2 lattice particles (a dummy as exactly one).
  const double dp2 = options_.dp * options_.dp;
  for (std::uint32_t k = wstart_[i]; k < wstart_[i + 1]; ++k)
    sigma += kernel_.W(wr_[k]) * (walls_.vol[wj_[k]] / dp2);
  return sigma;
}

void SphFluid::reinitialise_density() {
  auto& f = fluid_;
  const double rho0 = options_.rho0, inv_sigma0 = 1.0 / sigma0_;
  const bool free_surface = options_.free_surface;
  const double dp2 = options_.dp * options_.dp;
  parallel_for(f.size(), [&](std::size_t i) {
    const double rho_sum = rho0 * kernel_sum(i) * inv_sigma0;
    if (free_surface) {
      f.rho[i] = std::max(rho_sum, rho0);
      f.vol[i] = dp2;
    } else {
      f.rho[i] = rho_sum;
      f.vol[i] = mass_ / rho_sum;
    }
  });
}

} // namespace fsi::sph
