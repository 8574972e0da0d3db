// Issue 41 item 4: InterruptGuard is re-entrant. Nested or overlapping guards (a progress
// callback running another scene, two runs in two threads) leave the handler that was there
// before the first, and a signal stops every guarded run.
#include "fsi_app/interrupt.hpp"

#include <catch2/catch.hpp>
#include <csignal>

using fsi::app::InterruptGuard;

namespace {

void test_handler(int) {}

/// The handler SIGINT and SIGTERM now have.
std::pair<void (*)(int), void (*)(int)> handlers() {
  struct sigaction i = {}, t = {};
  sigaction(SIGINT, nullptr, &i);
  sigaction(SIGTERM, nullptr, &t);
  return {i.sa_handler, t.sa_handler};
}

} // namespace

TEST_CASE("apps: nested and overlapping interrupt guards restore the handler of before",
          "[apps][interrupt]") {
  struct sigaction mine = {}, old_int = {}, old_term = {};
  mine.sa_handler = test_handler;
  sigemptyset(&mine.sa_mask);
  sigaction(SIGINT, &mine, &old_int);
  sigaction(SIGTERM, &mine, &old_term);
  const auto before = handlers();
  SECTION("nested") {
    {
      InterruptGuard outer;
      const auto fsi_handlers = handlers();
      CHECK(fsi_handlers.first != test_handler);
      {
        InterruptGuard inner;
        CHECK(handlers() == fsi_handlers);
      }
      CHECK(handlers() == fsi_handlers); // still guarded: the outer run goes on
    }
    CHECK(handlers() == before);
  }
  SECTION("overlapping, the first ending first") {
    auto* a = new InterruptGuard;
    auto* b = new InterruptGuard;
    delete a;
    CHECK(handlers().first != test_handler);
    delete b;
    CHECK(handlers() == before);
  }
  SECTION("a signal during the inner run stops the outer one too") {
    InterruptGuard outer;
    {
      InterruptGuard inner;
      std::raise(SIGINT);
      CHECK(inner.received() == SIGINT);
    }
    CHECK(outer.received() == SIGINT);
  }
  SECTION("a run after nested ones starts without the old signal") {
    {
      InterruptGuard outer;
      InterruptGuard inner;
      std::raise(SIGTERM);
    }
    InterruptGuard next;
    CHECK(next.received() == 0);
  }
  sigaction(SIGINT, &old_int, nullptr);
  sigaction(SIGTERM, &old_term, nullptr);
}
