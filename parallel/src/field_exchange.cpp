#include "parallel/field_exchange.hpp"

#include <cassert>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace fsi::parallel {

namespace {
int to_int(std::size_t n) {
  // MPI counts are int: a rank sending more than 2 GiB at once needs derived types (not yet).
  if (n > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    throw std::length_error("FieldExchange: more than 2^31 bytes to one rank");
  return static_cast<int>(n);
}
} // namespace

void FieldExchange::plan(const Communicator& comm, const std::vector<std::uint32_t>& index,
                         const std::vector<int>& start) {
  const auto p = static_cast<std::size_t>(comm.size());
  assert(start.size() == p + 1 && static_cast<std::size_t>(start[p]) == index.size());
  index_.assign(index.begin(), index.end());
  start_.assign(start.begin(), start.end());
  std::vector<int> send_count(p), recv_count(p);
  for (std::size_t r = 0; r < p; ++r) send_count[r] = start_[r + 1] - start_[r];
  const CollectiveTimer timer;
  MPI_Alltoall(send_count.data(), 1, MPI_INT, recv_count.data(), 1, MPI_INT, comm.comm());
  recv_start_.assign(p + 1, 0);
  for (std::size_t r = 0; r < p; ++r) recv_start_[r + 1] = recv_start_[r] + recv_count[r];
  received_ = static_cast<std::size_t>(recv_start_[p]);
}

void FieldExchange::send(const Communicator& comm, const particles::FieldSet& fields,
                         const particles::FieldList& only) {
  const auto p = static_cast<std::size_t>(comm.size());
  only_ = only;
  const std::size_t record = fields.bytes_per_particle(only);
  send_bytes_.resize(p), send_displ_.resize(p), recv_bytes_.resize(p), recv_displ_.resize(p);
  for (std::size_t r = 0; r < p; ++r) {
    send_displ_[r] = to_int(static_cast<std::size_t>(start_[r]) * record);
    send_bytes_[r] = to_int(static_cast<std::size_t>(start_[r + 1] - start_[r]) * record);
    recv_displ_[r] = to_int(static_cast<std::size_t>(recv_start_[r]) * record);
    recv_bytes_[r] = to_int(static_cast<std::size_t>(recv_start_[r + 1] - recv_start_[r]) * record);
  }
  send_buf_.resize(index_.size() * record);
  recv_buf_.resize(received_ * record);
  // Rank r's block: field after field, each the values of r's entries in plan order.
  for (std::size_t r = 0; r < p; ++r) {
    std::byte* out = send_buf_.data() + send_displ_[r];
    fields.for_each_array(only, [&](const auto& values) {
      constexpr std::size_t bytes = sizeof(values[0]);
      for (int k = start_[r]; k < start_[r + 1]; ++k, out += bytes)
        std::memcpy(out, &values[index_[static_cast<std::size_t>(k)]], bytes);
    });
  }
  bytes_sent_ +=
      static_cast<double>(send_buf_.size() - static_cast<std::size_t>(send_bytes_[comm.rank()]));
  const CollectiveTimer timer;
  MPI_Alltoallv(send_buf_.data(), send_bytes_.data(), send_displ_.data(), MPI_BYTE,
                recv_buf_.data(), recv_bytes_.data(), recv_displ_.data(), MPI_BYTE, comm.comm());
}

void FieldExchange::unpack(particles::FieldSet& fields, std::size_t at) const {
  assert(at + received_ <= fields.size());
  const std::size_t p = recv_bytes_.size();
  for (std::size_t r = 0; r < p; ++r) {
    const std::byte* in = recv_buf_.data() + recv_displ_[r];
    const auto first = at + static_cast<std::size_t>(recv_start_[r]);
    const auto last = at + static_cast<std::size_t>(recv_start_[r + 1]);
    fields.for_each_array(only_, [&](auto& values) {
      constexpr std::size_t bytes = sizeof(values[0]);
      for (std::size_t i = first; i < last; ++i, in += bytes) std::memcpy(&values[i], in, bytes);
    });
  }
}

} // namespace fsi::parallel
