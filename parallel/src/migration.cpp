#include "parallel/migration.hpp"

#include <cassert>

namespace fsi::parallel {

void group_by_rank(const std::vector<int>& dest, int ranks, int skip,
                   std::vector<std::uint32_t>& index, std::vector<int>& start) {
  const auto p = static_cast<std::size_t>(ranks);
  start.assign(p + 1, 0);
  for (const int r : dest)
    if (r != skip) ++start[static_cast<std::size_t>(r) + 1];
  for (std::size_t r = 0; r < p; ++r) start[r + 1] += start[r];
  index.resize(static_cast<std::size_t>(start[p]));
  // Stable counting sort; start[r] walks through group r and is restored afterwards.
  for (std::size_t i = 0; i < dest.size(); ++i)
    if (dest[i] != skip)
      index[static_cast<std::size_t>(start[static_cast<std::size_t>(dest[i])]++)] =
          static_cast<std::uint32_t>(i);
  for (std::size_t r = p; r > 0; --r) start[r] = start[r - 1];
  start[0] = 0;
}

std::size_t Migration::migrate(const Communicator& comm, particles::FieldSet& fields,
                               const std::vector<int>& dest) {
  assert(dest.size() == fields.size());
  const int me = comm.rank();
  group_by_rank(dest, comm.size(), me, index_, start_);
  exchange_.plan(comm, index_, start_);
  exchange_.send(comm, fields); // packs before the set changes
  keep_.resize(dest.size());
  for (std::size_t i = 0; i < dest.size(); ++i) keep_[i] = dest[i] == me ? 1 : 0;
  const std::size_t left = fields.compact(keep_);
  const std::size_t kept = fields.size();
  fields.resize(kept + exchange_.received());
  exchange_.unpack(fields, kept);
  return left;
}

} // namespace fsi::parallel
