#include "decomposed_particles.hpp"

#include "fsi/core/error.hpp"

#include <algorithm>

namespace fsi::app {

template <int D>
particles::Decomposition<D>& DecomposedParticles<D>::decompose(const Ranks& ranks,
                                                               std::size_t particles) {
  if (!refusal_.empty()) throw InputError(refusal_);
  hook_ = ranks.particle_decomposition<D>(particles);
  ranks_ = &ranks;
  return *hook_;
}

template <int D> std::size_t DecomposedParticles<D>::global(std::size_t local) const {
  return hook_ ? static_cast<std::size_t>(hook_->sum(static_cast<double>(local))) : local;
}

template <int D> void DecomposedParticles<D>::gather_packed() {
  ranks_->gather(packed_, all_);
  const std::vector<double>& all = all_;
  const std::size_t k = k_, n = all.size() / k;
  order_.resize(n);
  for (std::size_t j = 0; j < n; ++j) order_[j] = j;
  std::sort(order_.begin(), order_.end(),
            [&](std::size_t a, std::size_t b) { return all[k * a] < all[k * b]; });
  sorted_.resize(k * n);
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t c = 0; c < k; ++c) sorted_[c * n + j] = all[k * order_[j] + c];
}

template class DecomposedParticles<2>;
template class DecomposedParticles<3>;

} // namespace fsi::app
