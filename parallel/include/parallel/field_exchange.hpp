#pragma once
// Sends chosen entries of every array of a FieldSet to other ranks with one MPI_Alltoallv: what
// migration and the halo exchange share. A plan lists, per destination rank, the indices to send;
// the values go field by field (every registered array, in FieldSet::names() order) in one byte
// buffer per destination, and arrive as the entries [at, at + received()) of the receiving set,
// ordered by source rank, then by the sender's plan order. Buffers are members, reused: once they
// are large enough a send allocates nothing.
#include "parallel/communicator.hpp"
#include "particles/field_set.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace fsi::parallel {

class FieldExchange {
public:
  /// Sets what goes where: index[k] for k in [start[r], start[r + 1]) goes to rank r (start has
  /// size() + 1 entries); exchanges the counts, so received() is known on return. Collective.
  void plan(const Communicator& comm, const std::vector<std::uint32_t>& index,
            const std::vector<int>& start);

  /// Packs the planned entries of the arrays of `fields` that `only` names (default: every
  /// array) and sends them (collective); the received values wait in the receive buffer until
  /// unpack().
  void send(const Communicator& comm, const particles::FieldSet& fields,
            const particles::FieldList& only = {});
  /// Writes the received values to entries [at, at + received()) of the arrays the last send()
  /// named (the caller sized `fields`; its arrays must be registered as on the sender).
  void unpack(particles::FieldSet& fields, std::size_t at) const;

  std::size_t received() const { return received_; }
  std::size_t sent() const { return index_.size(); }
  /// Bytes this rank has sent to other ranks over every send() so far.
  double bytes_sent() const { return bytes_sent_; }

private:
  std::vector<std::uint32_t> index_;
  std::vector<int> start_;                   // send groups, per rank + 1
  std::vector<int> recv_start_;              // receive groups (particles), per rank + 1
  std::vector<int> send_bytes_, send_displ_; // per rank, for MPI_Alltoallv
  std::vector<int> recv_bytes_, recv_displ_;
  std::vector<std::byte> send_buf_, recv_buf_;
  std::size_t received_ = 0;
  particles::FieldList only_; // the arrays of the last send()
  double bytes_sent_ = 0.0;
};

} // namespace fsi::parallel
