// Density re-initialisation once per advection step: rho_i = rho0 sigma_i / sigma0, the kernel
// sum over fluid and wall particles (method notes, "Kernel and resolution").
#include "fluid_sph/sph_fluid.hpp"

#include "fsi/core/parallel.hpp"

#include <algorithm>

namespace fsi::sph {

template <int D> double BasicSphFluid<D>::kernel_sum(std::size_t i) const {
  double sigma = kernel_.W(0.0);
  for (std::uint32_t k = pstart_[i]; k < pstart_[i + 1]; ++k) sigma += kernel_.W(pr_[k]);
  // A wall particle counts as V_a / dp^D lattice particles (a dummy as exactly one).
  const double cell = options_.cell_volume();
  for (std::uint32_t k = wstart_[i]; k < wstart_[i + 1]; ++k)
    sigma += kernel_.W(wr_[k]) * (walls_.vol[wj_[k]] / cell);
  return sigma;
}

template <int D> void BasicSphFluid<D>::reinitialise_density() {
  auto& f = fluid_;
  const double rho0 = options_.rho0, inv_sigma0 = 1.0 / sigma0_;
  const bool free_surface = options_.free_surface;
  const double cell = options_.cell_volume();
  parallel_for(owned(), [&](std::size_t i) {
    const double rho_sum = rho0 * kernel_sum(i) * inv_sigma0;
    if (free_surface) {
      f.rho[i] = std::max(rho_sum, rho0);
      f.vol[i] = cell;
    } else {
      f.rho[i] = rho_sum;
      f.vol[i] = mass_ / rho_sum;
    }
  });
}

template double BasicSphFluid<2>::kernel_sum(std::size_t) const;
template double BasicSphFluid<3>::kernel_sum(std::size_t) const;
template void BasicSphFluid<2>::reinitialise_density();
template void BasicSphFluid<3>::reinitialise_density();

} // namespace fsi::sph
