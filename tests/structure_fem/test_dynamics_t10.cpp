// Newmark-beta on T10 (issue 44): with beta = 1/4, gamma = 1/2 (the trapezoidal rule) and no
// load, the energy of a linear-elastic free vibration is conserved exactly, so over 1,000 steps
// it may move only by the Newton tolerance and round-off.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "sequential.hpp"
#include "structure_fem/box_mesher.hpp"
#include "structure_fem/structure.hpp"

using namespace fsi::fem;

TEST_CASE("T10 Newmark: energy conserved with beta = 1/4, gamma = 1/2",
          "[structure_fem][t10][dynamics][energy]") {
  const fem_test::Sequential sequential;
  const double L = 1.0, h = 0.1, E = 1.0e7, rho = 1000.0;
  StructureT10Options o;
  o.material = {E, 0.3, rho};
  o.clamped = {{"x_min", {true, true, true}, {}}};
  o.newmark = {0.25, 0.5};
  o.newton.residual_rtol = 1e-14;
  o.newton.increment_rtol = 1e-14;
  StructureT10 s(make_box_mesh({{0.0, 0.0, 0.0}, {L, h, h}, {8, 1, 1}}), o);
  // Initial velocity of the first bending shape's rough form, v_z = v0 (x / L)^2, with a tip
  // amplitude v0 / omega_1 of 1e-9 L. The trapezoidal rule conserves the energy of a linear
  // system only: St. Venant–Kirchhoff's drift grows with the amplitude (2.3e-10 at 1e-7 L,
  // 2.3e-12 at 1e-9 L, measured).
  const double omega1 = 1.875104 * 1.875104 / (L * L) * std::sqrt(E * h * h / (12.0 * rho));
  const double v0 = 1e-9 * L * omega1;
  Vector v = Vector::Zero(3 * static_cast<Eigen::Index>(s.mesh().num_nodes()));
  for (std::size_t k = 0; k < s.mesh().num_nodes(); ++k)
    if (s.mesh().X[k].x() > 0.0)
      v[3 * static_cast<Eigen::Index>(k) + 2] = v0 * std::pow(s.mesh().X[k].x() / L, 2);
  StructureState start = s.save();
  start.v = v;
  s.restore(start);
  s.update_acceleration(); // M a = -f_int(0) = 0
  const double E0 = s.energies().total();
  const double dt = 2.0 * std::numbers::pi / omega1 / 40.0;
  double drift = 0.0, strain_max = 0.0;
  long iterations = 0;
  for (int n = 0; n < 1000; ++n) {
    iterations += s.advance(dt).iterations;
    drift = std::max(drift, std::abs(s.energies().total() - E0) / E0);
    strain_max = std::max(strain_max, s.energies().strain / E0);
  }
  WARN("T10 Newmark beta = 1/4, gamma = 1/2: largest relative energy change over 1000 steps "
       << drift << " (25 periods of the first mode; strain energy up to " << strain_max
       << " of the total; " << iterations << " Newton iterations)");
  CHECK(strain_max > 0.5); // the energy did go back and forth between kinetic and strain
  CHECK(drift < 1e-10);
}
