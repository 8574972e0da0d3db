// Clamped particles: their prescribed motion (fixed, or a Clamp's position and velocity) and
// the odd images of a fixed clamp (u_g = -u_p mirrored across the clamp's face).
#include <cmath>
#include <string>
#include <utility>

#include "fsi/core/error.hpp"
#include "fsi/core/parallel.hpp"
#include "shared.hpp"
#include "solid_tlsph/solid.hpp"

namespace fsi::tlsph {

template <int D> void BasicTlsphSolid<D>::clamp_face(std::size_t k, Vec& point, Vec& normal) const {
  const BasicClamp<D>& c = options_.clamps[k];
  const double dp = options_.dp, tol = 1e-6 * dp;
  if (c.face_normal.norm() > 0.0) {
    point = c.face_point, normal = c.face_normal.normalized();
    return;
  }
  // The clamped-free pairs one lattice spacing apart: their directions give the normal, their
  // midpoints the face.
  Vec sum_d = Vec::Zero(), sum_m = Vec::Zero();
  std::vector<std::pair<Vec, Vec>> pairs; // (X_p - X_g, midpoint)
  for (std::size_t g = 0; g < size(); ++g) {
    if (clamped_[g] != k + 1) continue;
    for (std::uint32_t q = pair_start_[g]; q < pair_start_[g + 1]; ++q) {
      const std::uint32_t p = pair_b_[q];
      const Vec X_p = at(X0_, p), X_g = at(X0_, g);
      const Vec d = X_p - X_g;
      if (clamped_[p] || std::abs(d.norm() - dp) > tol) continue;
      const Vec m = 0.5 * (X_p + X_g);
      pairs.emplace_back(d, m), sum_d += d, sum_m += m;
    }
  }
  const std::string clamp = "tlsph: clamps[" + std::to_string(k) + "]";
  if (pairs.empty() || !(sum_d.norm() > 0.0))
    throw InputError(clamp + ": no clamped particle is dp from a free one; set face_point and "
                             "face_normal, or odd_image = false");
  normal = sum_d.normalized(), point = sum_m / static_cast<double>(pairs.size());
  for (const auto& [d, m] : pairs)
    if ((d - dp * normal).norm() > tol || std::abs((m - point).dot(normal)) > tol)
      throw InputError(clamp + ": the clamped particles do not meet the free ones on one "
                               "straight face (odd_image); set face_point and face_normal, or "
                               "odd_image = false");
}

template <int D> void BasicTlsphSolid<D>::build_images() {
  const std::size_t n = size(), clamps = options_.clamps.size();
  image_partner_.assign(n, none), image_of_.assign(n, none);
  imaged_.assign(clamps, 0);
  std::vector<Vec> face_point(clamps), face_normal(clamps);
  for (std::size_t k = 0; k < clamps; ++k) {
    const BasicClamp<D>& c = options_.clamps[k];
    imaged_[k] = c.odd_image && !c.position;
    if (!imaged_[k]) continue;
    bool any = false;
    for (std::size_t i = 0; i < n && !any; ++i) any = clamped_[i] == k + 1;
    if (any) clamp_face(k, face_point[k], face_normal[k]);
  }
  const double tol = 1e-6 * options_.dp;
  for (std::size_t g = 0; g < n; ++g) {
    if (!imaged(g)) continue;
    const std::size_t k = clamped_[g] - 1u;
    const Vec nrm = face_normal[k], X = at(X0_, g);
    const Vec M = X - 2.0 * (X - face_point[k]).dot(nrm) * nrm; // mirror position
    const std::size_t p = nearest_particle(M);
    if (!clamped_[p] && (at(X0_, p) - M).norm() <= tol) {
      image_partner_[g] = p, image_of_[p] = g;
      images_ = true;
      continue;
    }
    // No partner: the particle stays at X0 and must not be a free particle's neighbour.
    for (std::uint32_t q = pair_start_[g]; q < pair_start_[g + 1]; ++q)
      if (!clamped_[pair_b_[q]])
        throw InputError("tlsph: clamped particle " + std::to_string(g) +
                         " lies within 2h of "
                         "free particle " +
                         std::to_string(pair_b_[q]) +
                         " but has no free particle at its mirror position (odd_image)");
  }
  for (auto& a : image_a_) a.assign(n, 0.0);
}

template <int D> void BasicTlsphSolid<D>::prescribe(double t) {
  parallel_for(size(), [&](std::size_t i) {
    if (!clamped_[i]) return;
    const BasicClamp<D>& c = options_.clamps[clamped_[i] - 1u];
    const std::size_t p = image_partner_[i];
    if (p != none) { // u_g = -u_p, v_g = -v_p
      for (int k = 0; k < D; ++k) {
        x_[k][i] = X0_[k][i] - (x_[k][p] - X0_[k][p]);
        v_[k][i] = -v_[k][p], a_[k][i] = -a_[k][p];
      }
    } else if (c.position) {
      const Vec X = at(X0_, i);
      const Vec x = c.position(X, t), v = c.velocity(X, t);
      // a by a central difference of the prescribed velocity (output only: clamped particles
      // are not integrated).
      const double d = 1e-6 * (1.0 + std::abs(t));
      const Vec a = (c.velocity(X, t + d) - c.velocity(X, t - d)) / (2.0 * d);
      for (int k = 0; k < D; ++k) x_[k][i] = x(k), v_[k][i] = v(k), a_[k][i] = a(k);
    } else {
      for (int k = 0; k < D; ++k) x_[k][i] = X0_[k][i], v_[k][i] = a_[k][i] = 0.0;
    }
  });
}

template void BasicTlsphSolid<2>::clamp_face(std::size_t, Vec&, Vec&) const;
template void BasicTlsphSolid<3>::clamp_face(std::size_t, Vec&, Vec&) const;
template void BasicTlsphSolid<2>::build_images();
template void BasicTlsphSolid<3>::build_images();
template void BasicTlsphSolid<2>::prescribe(double);
template void BasicTlsphSolid<3>::prescribe(double);

} // namespace fsi::tlsph
