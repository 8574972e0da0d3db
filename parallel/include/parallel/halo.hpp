#pragma once
// Halo (ghost) particles: copies of the other ranks' particles within r_halo (the largest
// interaction radius plus the neighbour-list skin) of this rank's region, appended to the
// FieldSet after the owned ones, so a neighbour search over the whole set sees them. build()
// finds who needs what (each owned particle against every other rank's box: O(N P), enough for
// tens of ranks; a cut-tree box query is the step beyond); update() resends the same particles
// in the same order after their owners changed them (no re-search), as LAMMPS does between
// neighbour-list rebuilds.
#include "parallel/field_exchange.hpp"
#include "parallel/rcb_partition.hpp"
#include "particles/vector_field.hpp"

#include <cstdint>
#include <vector>

namespace fsi::parallel {

template <int D> class Halo {
  static_assert(D == 2 || D == 3, "the halo is instantiated for D = 2 and D = 3");

public:
  /// On a set without ghosts (drop() them first), appends copies of every other rank's particles at
  /// distance
  /// <= r_halo from boxes[rank] (collective). The set's first owned() entries are this rank's;
  /// entries [owned(), size()) are ghosts, ordered by owner rank, then by the owner's order.
  void build(const Communicator& comm, particles::FieldSet& fields,
             const particles::VectorField<D>& x, const std::vector<Box<D>>& boxes, double r_halo);
  /// Copies the owners' current values of the arrays `only` names (default: every array) onto
  /// the ghosts (collective).
  void update(const Communicator& comm, particles::FieldSet& fields,
              const particles::FieldList& only = {});
  /// Removes the ghosts (before a migration or a repartition).
  void drop(particles::FieldSet& fields) const { fields.resize(owned_); }

  std::size_t owned() const { return owned_; }
  std::size_t ghosts() const { return exchange_.received(); }
  /// How many copies of owned particles this rank sends per update.
  std::size_t sent() const { return exchange_.sent(); }
  /// Bytes this rank has sent over every build and update so far.
  double bytes_sent() const { return exchange_.bytes_sent(); }

private:
  FieldExchange exchange_;
  std::vector<std::uint32_t> index_;
  std::vector<int> start_;
  std::size_t owned_ = 0;
};

extern template class Halo<2>;
extern template class Halo<3>;

} // namespace fsi::parallel
