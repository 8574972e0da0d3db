// Wendland C2 in 2-D and 3-D: W integrates to 1 over R^D (midpoint quadrature on a fine Cartesian
// grid over the support, so a wrong normalisation constant fails) and dW/dr is W's derivative
// (central finite differences).
#include "particles/kernels.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace fsi::particles;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

/// Midpoint rule for the integral of W(|x|) over the cube [-2h, 2h]^D (the support) with m
/// cells per side.
template <int D> double integral(const BasicWendlandC2<D>& k, int m) {
  const double dx = 2.0 * k.cutoff() / m;
  const auto at = [&](int i) { return -k.cutoff() + (i + 0.5) * dx; };
  double s = 0.0;
  if constexpr (D == 2) {
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i) s += k.W(std::hypot(at(i), at(j)));
    return s * dx * dx;
  } else {
    for (int l = 0; l < m; ++l)
      for (int j = 0; j < m; ++j)
        for (int i = 0; i < m; ++i) s += k.W(std::hypot(at(i), at(j), at(l)));
    return s * dx * dx * dx;
  }
}

template <int D> void check_derivative(double h) {
  const BasicWendlandC2<D> k(h);
  const double e = 1e-6 * h;
  for (double q : {0.1, 0.5, 0.9, 1.3, 1.7, 1.95}) {
    const double r = q * h, fd = (k.W(r + e) - k.W(r - e)) / (2.0 * e);
    CHECK_THAT(k.dW(r), WithinRel(fd, 1e-6));
  }
  CHECK(k.dW(0.0) == 0.0);
  const double beyond = 1.000001 * k.cutoff(); // 2h itself may round to just inside
  CHECK(k.dW(beyond) == 0.0);
  CHECK(k.W(beyond) == 0.0);
}

} // namespace

TEST_CASE("particles: Wendland C2 integrates to 1 in 2-D and in 3-D", "[particles]") {
  const double h = 0.013;
  CHECK_THAT(integral(BasicWendlandC2<2>(h), 2000), WithinAbs(1.0, 1e-6));
  CHECK_THAT(integral(BasicWendlandC2<3>(h), 240), WithinAbs(1.0, 1e-6));
  // The 2-D kernel the 2-D solvers use is the D = 2 one: 7 / (4 pi h^2) at r = 0.
  CHECK(WendlandC2(h).W(0.0) == BasicWendlandC2<2>(h).W(0.0));
  CHECK_THAT(BasicWendlandC2<3>(h).W(0.0) / WendlandC2(h).W(0.0), WithinRel(0.75 / h, 1e-14));
}

TEST_CASE("particles: Wendland C2's dW/dr is the derivative of W in 2-D and in 3-D",
          "[particles]") {
  check_derivative<2>(0.013);
  check_derivative<3>(0.013);
}
