#pragma once
// The sub-step check shared by the T6 and T10 tests (test_substeps.cpp, test_substeps_t10.cpp).
#include <catch2/catch.hpp>

namespace fem_test {

/// One step dt under a sudden load(s, q): without sub-steps Newton fails within its 4 iterations
/// and leaves the state unchanged; with them (NewtonOptions::max_substep_levels) the step is
/// retried as n sub-steps, and equals those n sub-steps by hand with the forces
/// f^n + (f^{n+1} - f^n) i / n at the end of sub-step i. make(levels) builds the structure.
template <class Make, class Load>
void check_substeps_by_hand(const Make& make, const Load& load, double dt, double q) {
  auto plain = make(0);
  plain->set_external_forces(load(*plain, q));
  CHECK_THROWS_WITH(plain->advance(dt), Catch::Contains("Newton did not converge in 4"));
  CHECK(plain->time() == 0.0);

  auto retried = make(3);
  retried->set_external_forces(load(*retried, q));
  const auto report = retried->advance(dt);
  REQUIRE(report.substeps > 1);
  CHECK(retried->step() == 1);
  CHECK(retried->time() == dt);

  auto by_hand = make(0);
  const int n = report.substeps;
  for (int i = 1; i <= n; ++i) {
    by_hand->set_external_forces(load(*by_hand, q * i / n));
    by_hand->advance(dt / n);
  }
  const auto& u = retried->displacement();
  const double tip = u.cwiseAbs().maxCoeff();
  WARN("sub-steps: " << n << ", largest |u| " << tip << " m, difference from by hand "
                     << (u - by_hand->displacement()).cwiseAbs().maxCoeff() << " m");
  CHECK(tip > 0.01); // a large step: centimetres in 0.02 s
  CHECK((u - by_hand->displacement()).cwiseAbs().maxCoeff() < 1e-12 * tip);
  CHECK((retried->velocity() - by_hand->velocity()).cwiseAbs().maxCoeff() <
        1e-9 * by_hand->velocity().cwiseAbs().maxCoeff());
}

} // namespace fem_test
