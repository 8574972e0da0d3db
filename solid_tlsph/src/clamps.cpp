// Clamped particles: their prescribed motion (fixed, or a Clamp's position and velocity) and
// the odd images of a fixed clamp (u_g = -u_p mirrored across the clamp's face; u_g = +u_p
// mirrored across two faces in the corner where two clamps meet).
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
  image_partner_.assign(n, none), image_sign_.assign(n, -1.0);
  imaged_.assign(clamps, 0);
  std::vector<Vec> face_point(clamps, Vec::Zero()), face_normal(clamps, Vec::Zero());
  for (std::size_t k = 0; k < clamps; ++k) {
    const BasicClamp<D>& c = options_.clamps[k];
    imaged_[k] = c.odd_image && !c.position;
    if (!imaged_[k]) continue;
    bool any = false;
    for (std::size_t i = 0; i < n && !any; ++i) any = clamped_[i] == k + 1;
    if (any) clamp_face(k, face_point[k], face_normal[k]);
  }
  const double tol = 1e-6 * options_.dp;
  auto mirror = [&](const Vec& X, std::size_t k) {
    return Vec(X - 2.0 * (X - face_point[k]).dot(face_normal[k]) * face_normal[k]);
  };
  auto free_at = [&](const Vec& M) { // the free particle at M, or none
    const std::size_t p = nearest_particle(M);
    return !clamped_[p] && (at(X0_, p) - M).norm() <= tol ? p : none;
  };
  for (std::size_t g = 0; g < n; ++g) {
    if (!imaged(g)) continue;
    const std::size_t k = clamped_[g] - 1u;
    const Vec M = mirror(at(X0_, g), k);
    std::size_t p = free_at(M);
    // In the corner of two clamps: mirrored across the other's face too, u_g = +u_p.
    for (std::size_t k2 = 0; p == none && k2 < clamps; ++k2)
      if (k2 != k && imaged_[k2] && face_normal[k2].norm() > 0.0) {
        p = free_at(mirror(M, k2));
        if (p != none) image_sign_[g] = 1.0;
      }
    if (p != none) {
      image_partner_[g] = p;
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
  image_start_.assign(n + 1, 0); // each free particle's images, in particle order
  for (std::size_t g = 0; g < n; ++g)
    if (image_partner_[g] != none) ++image_start_[image_partner_[g] + 1];
  for (std::size_t p = 0; p < n; ++p) image_start_[p + 1] += image_start_[p];
  image_list_.assign(image_start_[n], 0);
  std::vector<std::uint32_t> next(image_start_.begin(), image_start_.end() - 1);
  for (std::size_t g = 0; g < n; ++g)
    if (image_partner_[g] != none)
      image_list_[next[image_partner_[g]]++] = static_cast<std::uint32_t>(g);
  for (auto& a : image_a_) a.assign(n, 0.0);
}

template <int D> void BasicTlsphSolid<D>::prescribe(double t) {
  parallel_for(size(), [&](std::size_t i) {
    if (!clamped_[i]) return;
    const BasicClamp<D>& c = options_.clamps[clamped_[i] - 1u];
    const std::size_t p = image_partner_[i];
    if (p != none) { // u_g = s u_p, v_g = s v_p
      const double s = image_sign_[i];
      for (int k = 0; k < D; ++k) {
        x_[k][i] = X0_[k][i] + s * (x_[k][p] - X0_[k][p]);
        v_[k][i] = s * v_[k][p], a_[k][i] = s * a_[k][p];
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
