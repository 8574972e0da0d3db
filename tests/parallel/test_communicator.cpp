// Communicator::exchange (MPI_Alltoallv of doubles, issue 47): what each rank receives is, in rank
// order, the part every rank addressed to it, empty parts included.
#include "parallel/communicator.hpp"

#include <catch2/catch.hpp>

#include <vector>

using fsi::parallel::Communicator;

TEST_CASE("exchange delivers each rank's parts in rank order", "[mpi]") {
  const Communicator comm;
  const int P = comm.size(), me = comm.rank();
  // Rank r sends rank d the values 1000 r + 10 d + i, i < d + 1, but nothing to itself when
  // there are other ranks.
  auto part = [&](int d) { return P > 1 && d == me ? 0 : d + 1; };
  std::vector<double> send;
  std::vector<int> counts;
  for (int d = 0; d < P; ++d) {
    counts.push_back(part(d));
    for (int i = 0; i < part(d); ++i) send.push_back(1000.0 * me + 10.0 * d + i);
  }
  std::vector<double> expected, received{-1.0};
  for (int r = 0; r < P; ++r)
    if (P == 1 || r != me)
      for (int i = 0; i <= me; ++i) expected.push_back(1000.0 * r + 10.0 * me + i);
  comm.exchange(send, counts, received);
  CHECK(received == expected);
}
