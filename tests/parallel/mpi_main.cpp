// The Catch2 main of the MPI tests: every rank runs every test case; the program fails on every
// rank if any rank saw a failure. Test cases assert on values reduced over all ranks (the same
// on each), so a failing check never leaves ranks waiting in different collectives.
#include <mpi.h>

#include "../catch_session.hpp"

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  // Rank 0 reports; the others run silently (their failures still count below).
  int failed = fsi_test::run_catch_session(argc, argv, rank != 0 ? "/dev/null" : nullptr);
  int any = 0;
  MPI_Allreduce(&failed, &any, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  MPI_Finalize();
  return any != 0 ? 1 : 0;
}
