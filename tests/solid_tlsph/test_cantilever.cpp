// Static cantilever under a small tip load against Timoshenko beam theory and structure_fem's
// T6 solution, by dynamic relaxation: mass damping 2 omega_1 (critical for the first mode, every
// other mode decays at least as fast) over 20 / omega_1 (residual ~ 21 e^-20 ~ 4e-8).
#include <catch2/catch.hpp>

#include <cmath>

#include "../structure_fem/cantilever.hpp"
#include "common.hpp"

using namespace tlsph_test;

namespace {

/// L = 1, H = 0.1, steel, plane strain; tip load P spread equally over the free-end column.
struct Result {
  double w;   ///< deflection (downwards) of the mid-height tip particle(s)
  double x;   ///< their x = L - dp / 2
  double ref; ///< Timoshenko at x
  double error() const { return w / ref - 1.0; }
};

constexpr double P = 1.0e4; // w / L ~ 2e-4: geometrically linear

Result static_tip(int layers, GradientCorrection c = GradientCorrection::linear) {
  Beam b;
  b.layers = layers;
  b.correction = c;
  auto o = beam_options(b);
  o.mass_damping = 2.0 * b.omega1();
  TlsphSolid s(beam_geometry(b), o);
  const auto tip = tip_column(s, b);
  std::vector<Vec2> f(s.size(), Vec2::Zero());
  for (const auto i : tip) f[i] = Vec2(0.0, -P / static_cast<double>(tip.size()));
  s.set_external_forces(f);
  relax(s, b.omega1(), 20.0);
  const double x = b.L - 0.5 * b.dp();
  return {-tip_displacement(s, b).y(), x, timoshenko_deflection(b, P, x)};
}

/// structure_fem's T6 beam (80 x 4 quads: a node every dp / 2 = 1/160 along x, so at x =
/// L - dp/2 for dp = H / 8) at the same point.
double fem_deflection(double x) {
  fem_test::Beam fb;
  fb.ex = 80, fb.ey = 4;
  fsi::fem::Structure fem(fem_test::beam_mesh(fb), fem_test::beam_options(fb));
  fem.set_external_forces(fem_test::tip_load(fem.mesh(), fb, P));
  fem.solve_static();
  return -fem.displacement()[2 * fem_test::node_at(fem.mesh(), {x, 0.5 * fb.h}) + 1];
}

} // namespace

TEST_CASE("tlsph: static cantilever converges to Timoshenko at second order (H/dp = 4, 8)",
          "[solid_tlsph][cantilever]") {
  const Result r4 = static_tip(4), r8 = static_tip(8);
  const double order = std::log2(r4.error() / r8.error());
  INFO("error vs Timoshenko: H/dp = 4 " << r4.error() << ", 8 " << r8.error() << "; order "
                                        << order);
  CHECK(order > 1.5);
}

TEST_CASE("tlsph: static cantilever, three resolutions: order and extrapolated deflection",
          "[solid_tlsph][cantilever][slow]") {
  const Result r4 = static_tip(4), r8 = static_tip(8), r16 = static_tip(16);
  // Observed order from the three solutions themselves (no reference needed), and the
  // Richardson extrapolation of the finest two.
  const double order = std::log2((r4.error() - r8.error()) / (r8.error() - r16.error()));
  const double w_ext = r16.w + (r16.w - r8.w) / (std::pow(2.0, order) - 1.0);
  const double w_fem = fem_deflection(r8.x);
  INFO("error vs Timoshenko: H/dp = 4 "
       << r4.error() << ", 8 " << r8.error() << ", 16 " << r16.error() << "; observed order "
       << order << "; extrapolated " << w_ext / r8.ref - 1.0 << "; FEM " << w_fem / r8.ref - 1.0);
  CHECK(order > 1.5);
  CHECK(std::abs(r16.error()) < std::abs(r8.error()));
  CHECK_THAT(w_ext, Catch::Matchers::WithinRel(r8.ref, 0.02));
  CHECK_THAT(w_ext, Catch::Matchers::WithinRel(w_fem, 0.02));
}

TEST_CASE("tlsph: static cantilever within 2 % of Timoshenko and FEM at H/dp = 8",
          "[solid_tlsph][cantilever][slow]") {
  const Result r8 = static_tip(8);
  const double w_fem = fem_deflection(r8.x);
  INFO("H/dp = 8: TL-SPH " << r8.w << ", Timoshenko " << r8.ref << ", FEM " << w_fem);
  CHECK_THAT(r8.w, Catch::Matchers::WithinRel(r8.ref, 0.02));
  CHECK_THAT(r8.w, Catch::Matchers::WithinRel(w_fem, 0.02));
}

TEST_CASE("tlsph quadratic: static cantilever within 2 % of Timoshenko and FEM at H/dp = 8",
          "[solid_tlsph][cantilever][quadratic][slow]") {
  const Result r8 = static_tip(8, GradientCorrection::quadratic);
  const double w_fem = fem_deflection(r8.x);
  INFO("H/dp = 8, quadratic: TL-SPH " << r8.w << " (" << r8.error() << " vs Timoshenko " << r8.ref
                                      << "), FEM " << w_fem);
  CHECK_THAT(r8.w, Catch::Matchers::WithinRel(r8.ref, 0.02));
  CHECK_THAT(r8.w, Catch::Matchers::WithinRel(w_fem, 0.02));
}

TEST_CASE("tlsph quadratic: static cantilever converges (H/dp = 4 8 16)",
          "[solid_tlsph][cantilever][quadratic][slow]") {
  const auto q = GradientCorrection::quadratic;
  const Result r4 = static_tip(4, q), r8 = static_tip(8, q), r16 = static_tip(16, q);
  INFO("quadratic, error vs Timoshenko: H/dp = 4 " << r4.error() << ", 8 " << r8.error() << ", 16 "
                                                   << r16.error());
  CHECK(std::abs(r16.error()) < std::abs(r8.error()));
  CHECK(std::abs(r8.error()) < std::abs(r4.error()));
  CHECK(std::abs(r16.error()) < 0.02);
}
