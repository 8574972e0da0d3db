#include "parallel/halo.hpp"

namespace fsi::parallel {

template <int D>
void Halo<D>::build(const Communicator& comm, particles::FieldSet& fields,
                    const particles::VectorField<D>& x, const std::vector<Box<D>>& boxes,
                    double r_halo) {
  owned_ = fields.size();
  const auto p = static_cast<std::size_t>(comm.size());
  const auto me = static_cast<std::size_t>(comm.rank());
  // Rank by rank, so each group comes out in the owner's order (counts first, then indices).
  start_.assign(p + 1, 0);
  index_.clear();
  VecD<D> xi;
  for (std::size_t r = 0; r < p; ++r) {
    if (r != me)
      for (std::size_t i = 0; i < owned_; ++i) {
        for (int a = 0; a < D; ++a) xi[a] = x[a][i];
        if (boxes[r].distance(xi) <= r_halo) index_.push_back(static_cast<std::uint32_t>(i));
      }
    start_[r + 1] = static_cast<int>(index_.size());
  }
  exchange_.plan(comm, index_, start_);
  exchange_.send(comm, fields);
  fields.resize(owned_ + exchange_.received());
  exchange_.unpack(fields, owned_);
}

template <int D>
void Halo<D>::update(const Communicator& comm, particles::FieldSet& fields,
                     const particles::FieldList& only) {
  exchange_.send(comm, fields, only);
  exchange_.unpack(fields, owned_);
}

template class Halo<2>;
template class Halo<3>;

} // namespace fsi::parallel
