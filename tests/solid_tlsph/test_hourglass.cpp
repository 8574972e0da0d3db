// Hourglass control of the quadratic correction (TlsphOptions::hourglass): the penalty on the
// residual of each particle's quadratic fit vanishes for quadratic fields and rigid motions,
// its force is -dPi/dx, and it stiffens the row-alternating zero-energy mode that a point load
// excites next to an odd-image clamp (docs/solid_tlsph.md, "Coupled").
#include <catch2/catch.hpp>

#include <cmath>

#include "common.hpp"

using namespace tlsph_test;

namespace {

/// 30 x 12 particles on [0, 0.3] x [0, 0.12], no clamp, the quadratic correction.
std::unique_ptr<TlsphSolid> hourglass_block(double hourglass) {
  TlsphOptions o;
  o.dp = 0.01;
  o.hourglass = hourglass;
  return std::make_unique<TlsphSolid>(fill_rectangle({0.0, 0.0}, {0.3, 0.12}, o.dp), o);
}

/// Strain energy (with the penalty) of the block displaced by u(X).
template <class Field> double energy(TlsphSolid& s, Field u) {
  std::vector<Vec2> x(s.size());
  for (std::size_t i = 0; i < s.size(); ++i)
    x[i] = s.reference_position(i) + u(s.reference_position(i));
  s.set_positions(x);
  return s.energies().strain;
}

/// The tiny coupled obstacle alone (6 x 20 free particles, dp = 2 mm, clamped below y = 0 by
/// its face), a point load of 0.05 N/m in +x on the surface particle X0 = (0.101, 0.005),
/// relaxed; returns u_x of the left column at y = 0.001, 0.003, ..., 0.013.
std::vector<double> point_load_column(double hourglass) {
  TlsphOptions o;
  o.dp = 0.002;
  o.material = {1.0e5, 0.3, 1000.0, fsi::materials::PlaneModel::plane_strain};
  o.hourglass = hourglass;
  o.mass_damping = 2.0 * 79.0; // 2 omega_1 of the obstacle
  Clamp clamp;
  clamp.contains = [](const Vec2& X) { return X.y() < 0.0; };
  o.clamps.push_back(clamp);
  TlsphSolid s(fill_rectangle({0.1, -0.008}, {0.112, 0.04}, o.dp), o);
  std::vector<Vec2> f(s.size(), Vec2::Zero());
  f[s.nearest_particle({0.101, 0.005})] = Vec2(0.05, 0.0);
  s.set_external_forces(f);
  s.advance(0.0, 30.0 / 79.0);
  std::vector<double> u;
  for (int j = 0; j < 7; ++j)
    u.push_back(s.displacement(s.nearest_particle({0.101, 0.001 + 0.002 * j})).x());
  return u;
}

/// Size of the row-alternating part of a column: max |u_j - (u_j-1 + u_j+1) / 2|.
double zigzag(const std::vector<double>& u) {
  double z = 0.0;
  for (std::size_t j = 1; j + 1 < u.size(); ++j)
    z = std::max(z, std::abs(u[j] - 0.5 * (u[j - 1] + u[j + 1])));
  return z;
}

} // namespace

TEST_CASE("tlsph hourglass: no penalty for quadratic fields and rigid motions, -dPi/dx for the "
          "row-alternating mode",
          "[solid_tlsph][hourglass]") {
  auto on = hourglass_block(TlsphOptions{}.hourglass), off = hourglass_block(0.0);
  const auto quadratic = [](const Vec2& X) {
    return Vec2(0.013 * X.x() - 0.021 * X.y() + 0.04 * X.x() * X.y() + 0.02 * X.y() * X.y(),
                0.007 * X.x() + 0.017 * X.y() + 0.03 * X.x() * X.x() - 0.01 * X.x() * X.y());
  };
  const double eq_on = energy(*on, quadratic), eq_off = energy(*off, quadratic);
  const double c = std::cos(0.4), s = std::sin(0.4);
  const auto rotation = [&](const Vec2& X) {
    return Vec2(c * X.x() - s * X.y() - X.x(), s * X.x() + c * X.y() - X.y());
  };
  const double er_on = energy(*on, rotation);
  // u_x = A (-1)^j on the rows j: at an interior particle F does not see it.
  const auto rows = [](const Vec2& X) {
    const long j = std::lround(X.y() / 0.01 - 0.5);
    return Vec2(j % 2 ? -1e-4 : 1e-4, 0.0);
  };
  const double ea_on = energy(*on, rows), ea_off = energy(*off, rows);
  INFO("quadratic field: energy " << eq_on << " with the penalty, " << eq_off
                                  << " without; rotation 0.4 rad: " << er_on
                                  << "; row-alternating: " << ea_on << " with, " << ea_off
                                  << " without");
  CHECK_THAT(eq_on, Catch::Matchers::WithinRel(eq_off, 1e-12));
  CHECK(std::abs(er_on) < 1e-12 * eq_on);
  // An interior particle's F does not see the alternating field (the material gives it no
  // energy there, only the surface rows do); the penalty does.
  std::vector<Vec2> x(on->size());
  for (std::size_t i = 0; i < on->size(); ++i)
    x[i] = on->reference_position(i) + rows(on->reference_position(i));
  on->set_positions(x);
  const std::size_t k = on->nearest_particle({0.155, 0.065});
  CHECK((on->deformation_gradient(k) - fsi::Mat2::Identity()).norm() < 1e-12);
  CHECK(ea_on - ea_off > 0.01 * ea_off);
  // The force on that particle is -dPi/dx (central difference): the penalty's alone.
  const Vec2 f = on->options().material.density * on->volume(k) * on->acceleration(k);
  const Vec2 grad = strain_energy_gradient(*on, x, k);
  INFO("interior particle: f = " << f.transpose() << ", -dPi/dx = " << -grad.transpose());
  CHECK((f + grad).norm() < 1e-5 * f.norm());
}

TEST_CASE("tlsph hourglass: a point load next to the face clamp no longer zig-zags the column",
          "[solid_tlsph][hourglass][image]") {
  const auto on = point_load_column(TlsphOptions{}.hourglass), off = point_load_column(0.0);
  INFO("u_x of the loaded column, y = 0.001 .. 0.013: with the penalty "
       << on[0] << " " << on[1] << " " << on[2] << " " << on[3] << " " << on[4] << " " << on[5]
       << " " << on[6] << "; without " << off[0] << " " << off[1] << " " << off[2] << " " << off[3]
       << " " << off[4] << " " << off[5] << " " << off[6] << "; zig-zag " << zigzag(on) << " / "
       << zigzag(off));
  CHECK(zigzag(on) < 0.2 * zigzag(off));
  for (const double u : on) CHECK(u > 0.0); // the whole column moves with the load
}
