// Accelerations on small maps with known answers (style item 17).
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include <Eigen/Dense>

#include "coupling/acceleration_aitken.hpp"
#include "coupling/acceleration_iqn_ils.hpp"
#include "coupling/registry.hpp"

using namespace fsi::coupling;

TEST_CASE("Aitken on a scalar linear map converges at its second update", "[coupling][accel]") {
  // x~ = lambda x + b with lambda = -3: plain iteration diverges; fixed point b / (1 - lambda).
  const double lambda = -3.0, b = 2.0, x_star = b / (1.0 - lambda);
  AitkenRelaxation aitken(0.5, 2.0);
  aitken.begin_step(Eigen::VectorXd());
  Eigen::VectorXd x(1), next;
  x << 0.0;
  auto h = [&](const Eigen::VectorXd& y) {
    return Eigen::VectorXd((lambda * y.array() + b).matrix());
  };
  aitken.update(x, h(x), next); // first update: omega = 0.5
  REQUIRE(aitken.relaxation().has_value());
  CHECK(*aitken.relaxation() == 0.5);
  CHECK(std::abs(next(0) - x_star) > 0.1);
  x = next;
  aitken.update(x, h(x), next); // second update: omega = 1 / (1 - lambda), exact
  CHECK_THAT(next(0), Catch::WithinAbs(x_star, 1e-14));
  CHECK_THAT(*aitken.relaxation(), Catch::WithinAbs(1.0 / (1.0 - lambda), 1e-14));
}

TEST_CASE("Aitken clamps the factor and keeps it across steps", "[coupling][accel]") {
  // lambda = 0.9: optimal omega = 10, clamped to omega_max = 2.
  AitkenRelaxation aitken(0.5, 2.0);
  aitken.begin_step(Eigen::VectorXd());
  Eigen::VectorXd x(1), next;
  x << 0.0;
  auto h = [&](const Eigen::VectorXd& y) {
    return Eigen::VectorXd((0.9 * y.array() + 1.0).matrix());
  };
  aitken.update(x, h(x), next);
  x = next;
  aitken.update(x, h(x), next);
  CHECK(*aitken.relaxation() == 2.0);
  aitken.end_step(true);
  aitken.begin_step(Eigen::VectorXd());
  aitken.update(x, h(x), next); // first factor of a new step: min(omega_init, |omega_prev|)
  CHECK(*aitken.relaxation() == 0.5);
}

namespace {

// Evaluations of x -> A x + b until ||r|| < 1e-10 ||r0||, with the given acceleration.
int solve_linear(Acceleration& acc, const Eigen::MatrixXd& a, const Eigen::VectorXd& b,
                 Eigen::VectorXd& x, int max_evaluations) {
  x = Eigen::VectorXd::Zero(b.size());
  acc.begin_step(Eigen::VectorXd());
  double r0 = -1.0;
  for (int it = 1; it <= max_evaluations; ++it) {
    const Eigen::VectorXd xt = a * x + b;
    const double r = (xt - x).norm();
    if (r0 < 0.0) r0 = r;
    if (r < 1e-10 * r0) {
      acc.end_step(true);
      return it;
    }
    Eigen::VectorXd next;
    acc.update(x, xt, next);
    x = next;
  }
  acc.end_step(false);
  return max_evaluations + 1;
}

} // namespace

TEST_CASE("IQN-ILS solves an n-dimensional linear fixed point in about n+1 iterations",
          "[coupling][accel]") {
  const int n = 5;
  std::mt19937 rng(11u);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::MatrixXd a(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) a(i, j) = u(rng);
  a *= 1.5 / a.eigenvalues().cwiseAbs().maxCoeff(); // spectral radius 1.5: plain BGS diverges
  Eigen::VectorXd b(n);
  for (int i = 0; i < n; ++i) b(i) = u(rng);
  const Eigen::VectorXd x_star = (Eigen::MatrixXd::Identity(n, n) - a).lu().solve(b);

  CouplingOptions o;
  o.reuse = 0;
  auto iqn = make_acceleration("iqn-ils", o);
  Eigen::VectorXd x;
  const int evaluations = solve_linear(*iqn, a, b, x, 50);
  // n + 1 updates (one relaxation, then n quasi-Newton ones), plus the evaluation that sees it.
  CHECK(evaluations <= n + 2);
  CHECK(evaluations >= n);
  CHECK((x - x_star).norm() < 1e-9 * x_star.norm());

  // With the columns of the previous solve reused, the same problem needs one update.
  CouplingOptions reuse = o;
  reuse.reuse = 1;
  IqnIlsAcceleration iqn_reuse(reuse.omega, reuse.reuse, reuse.iqn_filter);
  solve_linear(iqn_reuse, a, b, x, 50);
  CHECK(iqn_reuse.columns() == static_cast<std::size_t>(n));
  CHECK(solve_linear(iqn_reuse, a, b, x, 50) == 2);
  CHECK((x - x_star).norm() < 1e-9 * x_star.norm());

  // Aitken alone cannot do this for a non-scalar map within 2n evaluations.
  auto aitken = make_acceleration("aitken", o);
  CHECK(solve_linear(*aitken, a, b, x, 2 * n) > 2 * n);
}
