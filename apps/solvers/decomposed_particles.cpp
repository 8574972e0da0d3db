#include "decomposed_particles.hpp"

#include "fsi/core/error.hpp"

#include <algorithm>

namespace fsi::app {

template <int D>
FillBlock<D> DecomposedParticles<D>::setup(const Ranks& ranks, std::vector<VecD<D>> filled) {
  const std::size_t n = filled.size();
  if (!ranks.decomposed()) return setup(ranks, std::move(filled), 0, n);
  const particles::BlockRange b = particles::block_of(n, ranks.rank(), ranks.size());
  const auto first = filled.begin() + static_cast<std::ptrdiff_t>(b.first);
  return setup(ranks, std::vector<VecD<D>>(first, first + static_cast<std::ptrdiff_t>(b.size())),
               b.first, n);
}

template <int D>
FillBlock<D> DecomposedParticles<D>::setup(const Ranks& ranks, std::vector<VecD<D>> part,
                                           std::size_t first, std::size_t filled) {
  particles_ = filled_ = filled;
  if (!ranks.decomposed()) return {std::move(part), {}};
  return {std::move(part), {first, true}};
}

template <int D>
particles::Decomposition<D>& DecomposedParticles<D>::decompose(const Ranks& ranks) {
  if (!refusal_.empty()) throw InputError(refusal_);
  hook_ = ranks.particle_decomposition<D>(particles_);
  ranks_ = &ranks;
  own_rows_ = writes_collectively(ranks);
  return *hook_;
}

template <int D> std::size_t DecomposedParticles<D>::global(std::size_t local) const {
  return hook_ ? static_cast<std::size_t>(hook_->sum(static_cast<double>(local))) : local;
}

template <int D> JsonObject DecomposedParticles<D>::balance(std::size_t owned) const {
  const auto n = static_cast<double>(owned);
  const double waited = hook_->waited_seconds();
  JsonObject b; // the reductions below are collectives too: the figures are those before them
  b.add("owned_min", static_cast<long long>(hook_->min(n)))
      .add("owned_max", static_cast<long long>(hook_->max(n)))
      .add("waited_seconds_min", hook_->min(waited))
      .add("waited_seconds_max", hook_->max(waited))
      .add("partitions", static_cast<long long>(hook_->partitions()))
      .add("load_imbalance", hook_->load_imbalance());
  return b;
}

template <int D> void DecomposedParticles<D>::gather_packed() {
  if (own_rows_)
    all_.assign(packed_.begin(), packed_.end());
  else
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
  if (own_rows_) {
    place_rows();
    to_blocks();
  }
}

template <int D> void DecomposedParticles<D>::place_rows() {
  // The one-process file holds every particle in id order: an id's row is the number of ids
  // below it. Every id 0 .. total - 1 present (none removed): the id itself; otherwise counted
  // on a table of the ids present on some rank (8 bytes an id on every rank, summed).
  const std::size_t n = gathered();
  const double* id = column(0);
  rows_.total = global(n);
  const double top = hook_->max(n ? id[n - 1] : -1.0);
  places_.resize(n);
  if (top + 1.0 == static_cast<double>(rows_.total)) {
    for (std::size_t j = 0; j < n; ++j) places_[j] = static_cast<std::size_t>(id[j]);
    return;
  }
  present_.assign(static_cast<std::size_t>(top + 1.0), 0.0);
  for (std::size_t j = 0; j < n; ++j) present_[static_cast<std::size_t>(id[j])] = 1.0;
  ranks_->sum(present_);
  std::size_t below = 0, j = 0;
  for (std::size_t i = 0; i < present_.size() && j < n; ++i) {
    if (static_cast<std::size_t>(id[j]) == i) places_[j++] = below;
    below += present_[i] > 0.0;
  }
}

template <int D> void DecomposedParticles<D>::to_blocks() {
  // Rank r writes the places first(r) .. first(r + 1) - 1, first(r) = floor(r total / size), so
  // one hyperslab a dataset (a union of runs of ids is slow to select in HDF5). A place p is
  // rank ((p + 1) size - 1) / total's; places_ ascend, so each rank's rows are consecutive.
  const std::size_t n = gathered(), k = k_, total = rows_.total;
  const auto size = static_cast<std::size_t>(ranks_->size());
  const auto rank = static_cast<std::size_t>(ranks_->rank());
  counts_.assign(size, 0);
  send_.resize((k + 1) * n);
  for (std::size_t j = 0; j < n; ++j) {
    counts_[((places_[j] + 1) * size - 1) / total] += static_cast<int>(k + 1);
    send_[(k + 1) * j] = static_cast<double>(places_[j]);
    for (std::size_t c = 0; c < k; ++c) send_[(k + 1) * j + 1 + c] = sorted_[c * n + j];
  }
  ranks_->exchange(send_, counts_, all_);
  rows_.first = rank * total / size;
  rows_.count = (rank + 1) * total / size - rows_.first;
  sorted_.resize(k * rows_.count);
  for (std::size_t i = 0; i < rows_.count; ++i) {
    const double* row = &all_[(k + 1) * i];
    const auto j = static_cast<std::size_t>(row[0]) - rows_.first;
    for (std::size_t c = 0; c < k; ++c) sorted_[c * rows_.count + j] = row[1 + c];
  }
}

template class DecomposedParticles<2>;
template class DecomposedParticles<3>;

} // namespace fsi::app
