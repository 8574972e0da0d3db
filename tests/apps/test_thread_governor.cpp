// The run's thread governor (issue 48, item 3) on step times given by a model of the machine:
// the count it settles on, how often it tries another, and how it follows a change.
#include "fsi_app/thread_governor.hpp"

#include <catch2/catch.hpp>

#include <functional>

using fsi::app::ThreadGovernor;

namespace {

/// Runs `steps` steps whose wall time at n threads is seconds(step, n); returns the governor.
void drive(ThreadGovernor& g, long first, long steps,
           const std::function<double(long, int)>& seconds) {
  for (long s = first; s < first + steps; ++s) g.record(seconds(s, g.threads()));
}

/// A list rebuild every 18 steps costs 3 times a step: the window's median must not see it.
double with_rebuilds(long step, double t) {
  return step % 18 == 0 ? 3.0 * t : t;
}

} // namespace

TEST_CASE("apps: the thread governor keeps the asked count when it is the fastest", "[unit]") {
  ThreadGovernor g(2);
  drive(g, 0, 20000, [](long s, int n) { return with_rebuilds(s, n == 2 ? 0.52 : 1.0); });
  CHECK(g.threads() == 2);
  CHECK(g.switches() == 0);
  // The first trial after the first window of 9 steps, then 30, 60, ... 7,680 steps apart: 10
  // lost ones over 20,000 steps, each of at most 9 steps (a rebuild's step, over twice the
  // median, ends one at once).
  CHECK(g.trials() == 10);
  CHECK(g.steps_at()[0] <= 90);
  CHECK(static_cast<double>(g.steps_at()[0]) / 20000.0 < 0.005);
  CHECK(g.steps_at()[0] + g.steps_at()[1] == 20000);
}

TEST_CASE("apps: the thread governor drops to one thread when two are slower", "[unit]") {
  // A core shared with another process: two threads 9 times slower (measured with spinning
  // barriers, docs/performance.md).
  ThreadGovernor g(2);
  drive(g, 0, 200, [](long s, int n) { return with_rebuilds(s, n == 2 ? 9.0 : 1.0); });
  CHECK(g.threads() == 1);
  CHECK(g.switches() == 1);
  // Two threads for the first window (9 steps), then one step for each trial of two (at steps
  // 48 and 109), each ended at once.
  CHECK(g.steps_at()[1] == 11);
  // Staying at one: its trials of two lose at their first step and space out.
  drive(g, 200, 20000, [](long s, int n) { return with_rebuilds(s, n == 2 ? 9.0 : 1.0); });
  CHECK(g.threads() == 1);
  CHECK(g.switches() == 1);
  CHECK(g.steps_at()[1] == 9 + g.trials() - 1);
  CHECK(g.trials() <= 12);
}

TEST_CASE("apps: the thread governor follows the machine when the competitor leaves", "[unit]") {
  ThreadGovernor g(2);
  auto busy = [](long s, int n) { return with_rebuilds(s, n == 2 ? 1.3 : 1.0); };
  auto idle = [](long s, int n) { return with_rebuilds(s, n == 2 ? 0.52 : 1.0); };
  drive(g, 0, 1000, busy);
  REQUIRE(g.threads() == 1);
  drive(g, 1000, 8000, idle); // back to two within the longest period
  CHECK(g.threads() == 2);
  CHECK(g.switches() == 2);
  // A gain under the margin (5 %) does not switch.
  ThreadGovernor h(2);
  drive(h, 0, 5000, [](long s, int n) { return with_rebuilds(s, n == 2 ? 1.0 : 0.95); });
  CHECK(h.threads() == 2);
  CHECK(h.switches() == 0);
}

TEST_CASE("apps: the thread governor tries one fewer and one more between one and the most",
          "[unit]") {
  // Four threads asked, the best is three (one core taken by another process).
  ThreadGovernor g(4);
  auto machine = [](long s, int n) {
    const double t[] = {1.0, 0.55, 0.4, 0.8};
    return with_rebuilds(s, t[n - 1]);
  };
  drive(g, 0, 3000, machine);
  CHECK(g.threads() == 3);
  // With one asked it never tries another.
  ThreadGovernor one(1);
  drive(one, 0, 1000, [](long, int) { return 1.0; });
  CHECK(one.threads() == 1);
  CHECK(one.trials() == 0);
  CHECK(one.steps_at()[0] == 1000);
}
