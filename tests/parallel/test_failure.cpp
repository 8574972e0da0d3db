// A failure on some ranks only (issue 47): parallel::ParticleDecomposition::fail on one rank,
// then each of the hook's reductions throws RunError on every rank with the lowest failing
// rank's message naming it; without fail() the reductions are those of the Communicator.
#include "parallel/particle_decomposition.hpp"

#include <catch2/catch.hpp>

#include <functional>
#include <string>
#include <vector>

using namespace fsi;
using namespace fsi::parallel;

namespace {

/// What `reduction` threw on this rank ("" if nothing).
std::string thrown(const std::function<void()>& reduction) {
  try {
    reduction();
  } catch (const RunError& e) {
    return e.what();
  }
  return {};
}

} // namespace

TEST_CASE("a failure on one rank stops every rank at the next reduction", "[mpi]") {
  const Communicator comm;
  const int P = comm.size(), last = P - 1;
  ParticleDecomposition<2> hook(comm);
  const auto r = static_cast<double>(comm.rank());
  const std::string expected = "fluid: particle 7 at (1, 2) m (rank " + std::to_string(last) +
                               " of " + std::to_string(P) + ")";
  const std::vector<std::function<void()>> reductions = {
      [&] { hook.sum(r); }, [&] { hook.max(r); }, [&] { hook.min(r); }, [&] { hook.all(true); },
      [&] { hook.agree(); }};
  for (const auto& reduction : reductions) {
    // The last rank fails, then a second message on it and one on rank 0 (when P > 1): the
    // first fail() of the lowest failing rank is the one every rank reports.
    if (comm.rank() == last) hook.fail("fluid: particle 7 at (1, 2) m");
    if (comm.rank() == last) hook.fail("a later failure");
    const std::string what = thrown(reduction);
    CHECK(comm.all(what == expected));
    // Cleared after the agreed throw: the next reductions are plain again.
    CHECK(hook.sum(r) == comm.sum(r));
    CHECK(hook.max(r) == static_cast<double>(last));
    CHECK(hook.min(-r) == -static_cast<double>(last));
    CHECK(!hook.all(comm.rank() != last));
    CHECK(hook.all(true));
    CHECK(thrown([&] { hook.agree(); }).empty());
  }
  // Two ranks failing: rank 0's message, naming rank 0.
  if (P > 1) {
    if (comm.rank() == 0 || comm.rank() == last) hook.fail("rank " + std::to_string(comm.rank()));
    const std::string what = thrown([&] { hook.agree(); });
    CHECK(comm.all(what == "rank 0 (rank 0 of " + std::to_string(P) + ")"));
  }
}
