// Communicator::exchange (MPI_Alltoallv of doubles, issue 47): what each rank receives is, in rank
// order, the part every rank addressed to it, empty parts included; and the clock of the time
// spent waiting in collectives.
#include "parallel/communicator.hpp"

#include <catch2/catch.hpp>

#include <chrono>
#include <thread>
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

// collective_seconds (issue 47, run.json `ranks`): the last rank reaches a reduction 0.3 s after
// the others, so each other rank's clock grows by at least that wait and the late rank's by
// less than half of it.
TEST_CASE("collective_seconds counts the wait for the slowest rank", "[mpi]") {
  const Communicator comm;
  const int P = comm.size(), me = comm.rank();
  comm.sum(0.0); // every rank in step before the clocks are read
  const double before = fsi::parallel::collective_seconds();
  const bool late = me == P - 1;
  if (late) std::this_thread::sleep_for(std::chrono::milliseconds(300));
  CHECK(comm.sum(1.0) == P);
  const double waited = fsi::parallel::collective_seconds() - before;
  CHECK(waited >= 0.0);
  if (P > 1 && !late) CHECK(waited >= 0.29);
  if (late) CHECK(waited < 0.15);
}
