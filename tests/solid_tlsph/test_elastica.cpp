// Large deformation: a cantilever under a dead end load P (k = P L^2 / EI = 1, 2, 5) against
// the elastica, by dynamic relaxation (mass damping 2 omega_1 of the unloaded beam) with the
// load applied in steps of k. Measured as structure_fem's elastica test measures it: the
// mid-height point of the free end, deflection v and shortening u over L, each against the
// elastica's tip (s = L).
#include <catch2/catch.hpp>

#include <cmath>

#include "common.hpp"

using namespace tlsph_test;

namespace {

/// L = 1, H = 0.1, nu = 0, plane stress, EI = 1 (E = 12 / H^3).
Beam elastic_beam(int layers) {
  Beam b;
  b.L = 1.0, b.H = 0.1, b.nu = 0.0, b.rho = 1000.0;
  b.E = 12.0 / (b.H * b.H * b.H);
  b.plane = fsi::materials::PlaneModel::plane_stress;
  b.layers = layers;
  return b;
}

struct TipError {
  double k, v, u, v_ref, u_ref;
  double ev() const { return v / v_ref - 1.0; }
  double eu() const { return u / u_ref - 1.0; }
};

/// The end point's v, u against Euler's elastica at s = L (the reference).
std::vector<TipError> elastica_run(const Beam& b, const std::vector<double>& ks) {
  auto o = beam_options(b);
  o.mass_damping = 2.0 * b.omega1();
  TlsphSolid s(beam_geometry(b), o);
  const auto tip = tip_column(s, b);
  std::vector<TipError> out;
  for (const double k : ks) {
    std::vector<Vec2> f(s.size(), Vec2::Zero());
    for (const auto i : tip) f[i] = Vec2(0.0, -k / static_cast<double>(tip.size())); // EI = L = 1
    s.set_external_forces(f);
    relax(s, b.omega1(), 30.0);
    const Vec2 u = end_face_displacement(s, b);
    const Vec2 ref = elastica_point(k, b.L);
    out.push_back({k, -u.y(), -u.x(), ref.y(), b.L - ref.x()});
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

TEST_CASE("tlsph: elastica within 2 % of the analytic tip position (H/dp = 8)",
          "[solid_tlsph][elastica][slow]") {
  for (const auto& e : elastica_run(elastic_beam(8), {1.0, 2.0, 5.0})) {
    INFO("k = " << e.k << ": end point v " << e.v << " (elastica " << e.v_ref << ", " << e.ev()
                << "), u " << e.u << " (elastica " << e.u_ref << ", " << e.eu() << ")");
    CHECK_THAT(e.v, Catch::Matchers::WithinRel(e.v_ref, 0.02));
    CHECK_THAT(e.u, Catch::Matchers::WithinRel(e.u_ref, 0.02));
  }
}
