#pragma once
// Migration: every particle to the rank that owns it now (after a partition, or after it moved
// out of its owner's region), all registered arrays of the FieldSet together, with one
// MPI_Alltoallv. Dimension-free: the destinations come from the partition.
#include "parallel/field_exchange.hpp"

#include <cstdint>
#include <vector>

namespace fsi::parallel {

class Migration {
public:
  /// Sends particle i to rank dest[i] (dest.size() == fields.size(), no ghosts in the set);
  /// collective. Afterwards the set holds the particles that stayed, in their order, then the
  /// received ones by source rank, each in its sender's order. Returns how many left this rank.
  std::size_t migrate(const Communicator& comm, particles::FieldSet& fields,
                      const std::vector<int>& dest);

private:
  FieldExchange exchange_;
  std::vector<std::uint32_t> index_;
  std::vector<int> start_;
  std::vector<std::uint8_t> keep_;
};

/// Group indices by rank: index[k], k in [start[r], start[r + 1]), are the i with dest[i] == r,
/// in increasing order, for every r != skip (pass skip = -1 to keep all). Reuses the buffers.
void group_by_rank(const std::vector<int>& dest, int ranks, int skip,
                   std::vector<std::uint32_t>& index, std::vector<int>& start);

} // namespace fsi::parallel
