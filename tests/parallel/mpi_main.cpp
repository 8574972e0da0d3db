// The Catch2 main of the MPI tests: every rank runs every test case; the program fails on every
// rank if any rank saw a failure. Test cases assert on values reduced over all ranks (the same
// on each), so a failing check never leaves ranks waiting in different collectives.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>
#include <mpi.h>

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  Catch::Session session;
  // Rank 0 reports; the others run silently (their failures still count below).
  if (rank != 0) session.configData().outputFilename = "/dev/null";
  int failed = session.run(argc, argv);
  int any = 0;
  MPI_Allreduce(&failed, &any, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  MPI_Finalize();
  return any != 0 ? 1 : 0;
}
