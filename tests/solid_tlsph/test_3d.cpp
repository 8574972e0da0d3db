// The TL-SPH solid in 3-D (BasicTlsphSolid<3>): the corrected gradients and F exact for affine
// (and, quadratic correction, quadratic) fields on a perturbed lattice, the stress forces'
// sign and their conservation of momentum and angular momentum, and a clamped cantilever
// against Timoshenko beam theory (tip deflection, first bending frequency).
#include <catch2/catch.hpp>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "solid_tlsph/solid.hpp"

namespace {

using fsi::Mat3;
using fsi::Vec3;
using namespace fsi::tlsph;

constexpr GradientCorrection both[] = {GradientCorrection::linear, GradientCorrection::quadratic};

const char* name(GradientCorrection c) {
  return c == GradientCorrection::linear ? "linear" : "quadratic";
}

/// A 6 x 5 x 4 block at dp = 0.01, optionally every particle moved by up to 0.15 dp per axis.
TlsphSolid3 jittered_block(GradientCorrection c, double jitter) {
  TlsphOptions3 o;
  o.dp = 0.01;
  o.gradient_correction = c;
  o.material = {1.0e6, 0.3, 1000.0, fsi::materials::PlaneModel::plane_strain};
  SolidGeometry3 g = fill_box(Vec3::Zero(), Vec3(0.06, 0.05, 0.04), o.dp);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> shift(-jitter * o.dp, jitter * o.dp);
  for (Vec3& X : g.X0) X += Vec3(shift(rng), shift(rng), shift(rng));
  return TlsphSolid3(g, o);
}

/// Sets x = phi(X) at every particle.
template <class Map> void deform(TlsphSolid3& s, Map phi) {
  std::vector<Vec3> x(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) x[i] = phi(s.reference_position(i));
  s.set_positions(x);
}

const Mat3 A =
    (Mat3() << 1.02, 0.013, -0.007, -0.011, 0.985, 0.021, 0.004, -0.016, 1.01).finished();

} // namespace

TEST_CASE("tlsph 3-D: F of an affine motion is A to round-off on a perturbed lattice",
          "[solid_tlsph][3d]") {
  const Vec3 b(0.3, -0.2, 0.1);
  for (const GradientCorrection c : both) {
    TlsphSolid3 s = jittered_block(c, 0.15);
    deform(s, [&](const Vec3& X) { return Vec3(A * X + b); });
    double err = 0.0;
    for (std::size_t i = 0; i < s.size(); ++i)
      err = std::max(err, (s.deformation_gradient(i) - A).cwiseAbs().maxCoeff());
    INFO(name(c) << ": max |F - A| = " << err << " over " << s.size() << " particles");
    CHECK(err < 1e-12);
  }
}

TEST_CASE("tlsph 3-D: the quadratic correction's F is exact for a quadratic field, the linear "
          "one's is not at the surface",
          "[solid_tlsph][3d]") {
  // u = (k/2) (X_y^2 + X_z^2, 0, 0) + ...: grad u = k (0, X_y, X_z; ...) varies linearly
  const double k = 0.5;
  auto phi = [&](const Vec3& X) {
    return Vec3(X.x() + 0.5 * k * (X.y() * X.y() + X.z() * X.z()), X.y() + k * X.x() * X.z(),
                X.z() - 0.5 * k * X.x() * X.x());
  };
  auto F_exact = [&](const Vec3& X) {
    Mat3 F;
    F << 1.0, k * X.y(), k * X.z(), k * X.z(), 1.0, k * X.x(), -k * X.x(), 0.0, 1.0;
    return F;
  };
  double err[2] = {0.0, 0.0};
  for (const GradientCorrection c : both) {
    TlsphSolid3 s = jittered_block(c, 0.15);
    deform(s, phi);
    double& e = err[c == GradientCorrection::quadratic];
    for (std::size_t i = 0; i < s.size(); ++i)
      e = std::max(
          e, (s.deformation_gradient(i) - F_exact(s.reference_position(i))).cwiseAbs().maxCoeff());
  }
  INFO("max |F - F_exact|: linear " << err[0] << ", quadratic " << err[1]);
  CHECK(err[1] < 1e-12);
  CHECK(err[0] > 1e-4); // k dp = 5e-3: the one-sided stencils' first-order error
}

TEST_CASE("tlsph 3-D: a stretched block's forces restore it, conserve momentum and angular "
          "momentum",
          "[solid_tlsph][3d]") {
  const double eps = 1e-3;
  const Vec3 centre(0.03, 0.025, 0.02);
  const Mat3 R = Eigen::AngleAxisd(0.7, Vec3(1.0, 2.0, 3.0).normalized()).toRotationMatrix();
  for (const GradientCorrection c : both) {
    TlsphSolid3 s = jittered_block(c, 0.0);
    // Uniaxial stretch along x about the centre, then a rigid rotation R and a shift.
    deform(s, [&](const Vec3& X) {
      Vec3 d = X - centre;
      d.x() *= 1.0 + eps;
      return Vec3(R * d + centre + Vec3(0.1, 0.0, 0.0));
    });
    Vec3 force = Vec3::Zero(), moment = Vec3::Zero();
    double scale = 0.0, restoring = 0.0;
    int outer = 0, inwards = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
      const Vec3 f = 1000.0 * s.volume(i) * s.acceleration(i); // m a, no load or gravity
      force += f, moment += s.position(i).cross(f), scale += f.norm();
      const Vec3 f_ref = R.transpose() * f; // in the block's axes
      const double X = s.reference_position(i).x();
      if (std::abs(X - 0.005) < 1e-9 || std::abs(X - 0.055) < 1e-9) {  // the two end layers
        const double f_in = f_ref.x() * (X < centre.x() ? 1.0 : -1.0); // > 0: pulled back
        ++outer, inwards += f_in > 0.0, restoring += f_in;
      }
    }
    INFO(name(c) << ": |sum f| = " << force.norm() << ", |sum x x f| = " << moment.norm()
                 << ", sum |f| = " << scale << ", restoring " << restoring << " N over " << outer
                 << " end particles, " << inwards << " of them pulled inwards");
    CHECK(outer == 2 * 5 * 4);
    CHECK(inwards == outer);
    CHECK(restoring > 0.1 * scale);
    CHECK(force.norm() < 1e-12 * scale);
    CHECK(moment.norm() < 1e-12 * scale * 0.1);
  }
}

TEST_CASE("tlsph 3-D: next to an odd-image clamp the force is -dPi/dx (central difference)",
          "[solid_tlsph][3d]") {
  // One clamp at x < 0; or a second at y < 0 meeting it (the corner's images: u_g = +u_p).
  for (const bool corner : {false, true})
    for (const GradientCorrection c : both) {
      TlsphOptions3 o;
      o.dp = 0.01;
      o.gradient_correction = c;
      o.material = {1.0e6, 0.3, 1000.0, fsi::materials::PlaneModel::plane_strain};
      Clamp3 clamp;
      clamp.contains = [](const Vec3& X) { return X.x() < 0.0; }; // face x = 0, found
      o.clamps.push_back(clamp);
      if (corner) {
        clamp.contains = [](const Vec3& X) { return X.y() < 0.0; }; // face y = 0
        o.clamps.push_back(clamp);
      }
      const double y0 = corner ? -0.03 : 0.0;
      TlsphSolid3 s(fill_box(Vec3(-0.03, y0, 0.0), Vec3(0.06, 0.04, 0.04), o.dp), o);
      std::vector<Vec3> x(s.size());
      for (std::size_t i = 0; i < s.size(); ++i) {
        const Vec3 X = s.reference_position(i);
        x[i] = X + 0.02 * Vec3(X.y() * X.z() / 0.04, X.x() * X.x() / 0.06, 0.5 * X.x());
      }
      s.set_positions(x);
      // a free particle at the clamp face's corner, and one inside next to the face
      for (const Vec3& X : {Vec3(0.005, 0.005, 0.035), Vec3(0.005, 0.025, 0.015)}) {
        const std::size_t p = s.nearest_particle(X);
        REQUIRE_FALSE(s.clamped(p));
        const Vec3 f = 1000.0 * s.volume(p) * s.acceleration(p);
        Vec3 grad;
        const double d = 1e-8;
        for (int k = 0; k < 3; ++k) {
          std::vector<Vec3> xp = x, xm = x;
          xp[p](k) += d, xm[p](k) -= d;
          s.set_positions(xp);
          const double Pp = s.energies().strain;
          s.set_positions(xm);
          grad(k) = (Pp - s.energies().strain) / (2.0 * d);
        }
        s.set_positions(x);
        INFO(name(c) << (corner ? ", two clamps" : "") << ": particle " << p
                     << " f = " << f.transpose() << ", -dPi/dx = " << -grad.transpose());
        CHECK((f + grad).norm() < 1e-5 * f.norm());
      }
    }
}

TEST_CASE("tlsph 3-D: pure bending's strain energy is the lattice midpoint rule's, "
          "(1 - (dp/H)^2) of the beam's",
          "[solid_tlsph][3d]") {
  // The exact linear-elastic pure bending of a prism (y from mid-height, curvature k):
  // u = (-k x y, k (x^2 + nu (y^2 - z^2)) / 2, nu k y z), sigma_xx = -E k y alone, so the energy
  // is E k^2 L B H^3 / 24. The field is quadratic: with the quadratic correction F is exact at
  // every particle (hourglass residual zero), and sum_a V_a W(F_a) is the midpoint rule over
  // the H/dp layers, sum dp y_a^2 = H^3/12 - H dp^2/12: the bending stiffness of a particle beam
  // is (1 - (dp/H)^2) of the continuum's (docs/solid_tlsph.md, "3-D cantilever: the split").
  const double L = 0.06, H = 0.04, B = 0.03, dp = 0.01, k = 1e-4, Y = 1.0e6, nu = 0.3;
  for (const GradientCorrection c : both) {
    TlsphOptions3 o;
    o.dp = dp;
    o.gradient_correction = c;
    o.material = {Y, nu, 1000.0, fsi::materials::PlaneModel::plane_strain};
    TlsphSolid3 s(fill_box(Vec3::Zero(), Vec3(L, H, B), dp), o);
    deform(s, [&](const Vec3& X) {
      const double x = X.x(), y = X.y() - 0.5 * H, z = X.z() - 0.5 * B;
      return Vec3(X + Vec3(-k * x * y, 0.5 * k * (x * x + nu * (y * y - z * z)), nu * k * y * z));
    });
    const double ratio = s.energies().strain / (Y * k * k * L * B * std::pow(H, 3) / 24.0);
    const double midpoint = 1.0 - (dp / H) * (dp / H); // 0.9375 at H/dp = 4
    INFO(name(c) << ": energy / exact = " << ratio << ", lattice midpoint rule " << midpoint);
    if (c == GradientCorrection::quadratic)
      CHECK_THAT(ratio, Catch::Matchers::WithinRel(midpoint, 1e-4));
    else // the linear correction's surface F error lowers it further (first order in dp)
      CHECK(ratio < midpoint - 0.02);
  }
}
