#include "parallel/particle_decomposition.hpp"

#include <algorithm>

namespace fsi::parallel {

template <int D>
ParticleDecomposition<D>::ParticleDecomposition(const Communicator& comm, double rebalance)
    : comm_(comm), rebalance_(rebalance), rcb_(comm) {}

template <int D>
bool ParticleDecomposition<D>::migrate(particles::FieldSet& fields,
                                       const particles::VectorField<D>& x,
                                       const std::vector<double>* work) {
  drop_ghosts(fields);
  const bool first = rcb_.partitions() == 0;
  const std::size_t n = fields.size();
  double load = static_cast<double>(n);
  if (work) { // the set's array
    load_.resize(n);
    for (std::size_t i = 0; i < n; ++i) load_[i] = static_cast<float>(1.0 + (*work)[i]);
    load = 0.0;
    for (const float l : load_) load += l;
  }
  imbalance_ = imbalance(comm_, load);
  if (first || imbalance_ > rebalance_)
    rcb_.partition(x.coords(), n, work ? std::span<const float>(load_) : std::span<const float>(),
                   dest_);
  else
    rcb_.owners(x.coords(), fields.size(), dest_);
  const std::size_t before = fields.size();
  const std::size_t left = migration_.migrate(comm_, fields, dest_);
  ++migrations_;
  emigrants_ += static_cast<long>(left);
  return first || left > 0 || fields.size() + left != before; // the last: some arrived
}

template <int D>
void ParticleDecomposition<D>::build_ghosts(particles::FieldSet& fields,
                                            const particles::VectorField<D>& x, double reach) {
  const Box<D>& mine = rcb_.boxes()[static_cast<std::size_t>(comm_.rank())];
  double out = 0.0; // the farthest owned particle outside this rank's box
  VecD<D> xi;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    for (int a = 0; a < D; ++a) xi[a] = x[a][i];
    out = std::max(out, mine.distance(xi));
  }
  halo_.build(comm_, fields, x, rcb_.boxes(), reach + comm_.max(out));
  active_ = true;
  ++halo_builds_;
}

template <int D>
void ParticleDecomposition<D>::update_ghosts(particles::FieldSet& fields,
                                             const particles::FieldList& changed) {
  if (active_) halo_.update(comm_, fields, changed);
}

template <int D> void ParticleDecomposition<D>::drop_ghosts(particles::FieldSet& fields) {
  if (active_) halo_.drop(fields);
  active_ = false;
}

template <int D> void ParticleDecomposition<D>::fail(const std::string& what) {
  if (failure_.empty()) failure_ = what.empty() ? std::string("failed") : what;
}

template <int D> double ParticleDecomposition<D>::agreed(Communicator::Flagged reduced) const {
  if (!reduced.failed) return reduced.value;
  const std::string message = comm_.first_failure(failure_, failing());
  failure_.clear();
  throw RunError(message);
}

template class ParticleDecomposition<2>;
template class ParticleDecomposition<3>;

} // namespace fsi::parallel
