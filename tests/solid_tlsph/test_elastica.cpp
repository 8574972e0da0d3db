// Large deformation: a cantilever under a dead end load P (k = P L^2 / EI = 1, 2, 5) against
// the elastica, by dynamic relaxation (mass damping 2 omega_1 of the unloaded beam) with the
// load applied in steps of k.
#include <catch2/catch.hpp>

#include <cmath>

#include "common.hpp"

using namespace tlsph_test;

namespace {

/// L = 1, H = 0.1, nu = 0, plane stress, EI = 1 (E = 12 / H^3): shear adds 0.6 (H/L)^2 = 0.6 %
/// to the linear deflection, the elastica (inextensible, no shear) the reference.
Beam elastic_beam(int layers, GradientCorrection c = GradientCorrection::linear,
                  bool odd_image = false) {
  Beam b;
  b.correction = c;
  b.odd_image = odd_image;
  b.L = 1.0, b.H = 0.1, b.nu = 0.0, b.rho = 1000.0;
  b.E = 12.0 / (b.H * b.H * b.H);
  b.plane = fsi::materials::PlaneModel::plane_stress;
  b.layers = layers;
  return b;
}

struct TipError {
  double k, v, u, v_ref, u_ref;
};

/// The mid-height tip particle(s) at arc length s = L - dp/2 against the elastica there.
std::vector<TipError> elastica_run(int layers, const std::vector<double>& ks,
                                   GradientCorrection c = GradientCorrection::linear,
                                   bool odd_image = false) {
  const Beam b = elastic_beam(layers, c, odd_image);
  auto o = beam_options(b);
  o.mass_damping = 2.0 * b.omega1();
  TlsphSolid s(beam_geometry(b), o);
  const auto tip = tip_column(s, b);
  std::vector<TipError> out;
  const double s_probe = b.L - 0.5 * b.dp();
  for (const double k : ks) {
    std::vector<Vec2> f(s.size(), Vec2::Zero());
    for (const auto i : tip) f[i] = Vec2(0.0, -k / static_cast<double>(tip.size())); // EI = L = 1
    s.set_external_forces(f);
    relax(s, b.omega1(), 30.0);
    const Vec2 u = tip_displacement(s, b);
    const Vec2 ref = elastica_point(k, s_probe);
    out.push_back({k, -u.y(), -u.x(), ref.y(), s_probe - ref.x()});
  }
  return out;
}

} // namespace

TEST_CASE("tlsph: elastica reference reproduces Mattiasson's tip values",
          "[solid_tlsph][elastica]") {
  const Vec2 k1 = elastica_point(1.0, 1.0), k10 = elastica_point(10.0, 1.0);
  CHECK_THAT(k1.y(), Catch::Matchers::WithinAbs(0.30172, 2e-5));
  CHECK_THAT(1.0 - k1.x(), Catch::Matchers::WithinAbs(0.05643, 2e-5));
  CHECK_THAT(k10.y(), Catch::Matchers::WithinAbs(0.81061, 2e-5));
  CHECK_THAT(1.0 - k10.x(), Catch::Matchers::WithinAbs(0.55500, 2e-5));
}

TEST_CASE("tlsph: elastica error shrinks with resolution (k = 2, H/dp = 4, 8)",
          "[solid_tlsph][elastica]") {
  const auto c = elastica_run(4, {2.0}), f = elastica_run(8, {2.0});
  const double ec = c[0].v / c[0].v_ref - 1.0, ef = f[0].v / f[0].v_ref - 1.0;
  INFO("k = 2 tip deflection error: H/dp = 4 " << ec << ", 8 " << ef);
  CHECK(std::log2(ec / ef) > 1.5);
}

TEST_CASE("tlsph: elastica within 2 % of the analytic tip position (H/dp = 8)",
          "[solid_tlsph][elastica][slow]") {
  for (const auto& e : elastica_run(8, {1.0, 2.0, 5.0})) {
    INFO("k = " << e.k << ": v " << e.v << " (elastica " << e.v_ref << "), u " << e.u
                << " (elastica " << e.u_ref << ")");
    CHECK_THAT(e.v, Catch::Matchers::WithinRel(e.v_ref, 0.02));
    CHECK_THAT(e.u, Catch::Matchers::WithinRel(e.u_ref, 0.02));
  }
}

TEST_CASE("tlsph quadratic: elastica within 2 % of the analytic tip position (H/dp = 8)",
          "[solid_tlsph][elastica][quadratic][slow]") {
  for (const auto& e : elastica_run(8, {1.0, 2.0, 5.0}, GradientCorrection::quadratic)) {
    INFO("quadratic, k = " << e.k << ": v " << e.v << " (elastica " << e.v_ref << "), u " << e.u
                           << " (elastica " << e.u_ref << ")");
    CHECK_THAT(e.v, Catch::Matchers::WithinRel(e.v_ref, 0.02));
    CHECK_THAT(e.u, Catch::Matchers::WithinRel(e.u_ref, 0.02));
  }
}

TEST_CASE("tlsph quadratic + odd-image clamp: elastica within 2 % (H/dp = 8)",
          "[solid_tlsph][elastica][quadratic][image][slow]") {
  for (const auto& e : elastica_run(8, {1.0, 2.0, 5.0}, GradientCorrection::quadratic, true)) {
    INFO("quadratic, odd-image clamp, k = " << e.k << ": v " << e.v << " (elastica " << e.v_ref
                                            << "), u " << e.u << " (elastica " << e.u_ref << ")");
    CHECK_THAT(e.v, Catch::Matchers::WithinRel(e.v_ref, 0.02));
    CHECK_THAT(e.u, Catch::Matchers::WithinRel(e.u_ref, 0.02));
  }
}
