// The viscous part of the EMPS step's first stage (eqs. 11, 13, 24) and the closing-pair
// viscosities.
#include "fluid_emps/emps_fluid.hpp"
#include "fsi/core/parallel.hpp"
#include "step_timer.hpp"

#include <array>
#include <cmath>
#include <type_traits>

namespace fsi::emps {

// nu <lap v>^ERP into scratch_ (eqs. 11, 24; advance adds it and g to v, eq. 13, the wall terms
// over up to three faces in 3-D); in 2-D the
// walls' viscous array keeps each face's viscous wall force (with wall_approach_viscosity
// alpha_w, also alpha_w c l0 times the mirror closing-pair sum of WallTerms::mirror_viscous, a
// wall force).
// With artificial_viscosity alpha, closing pairs also feel alpha c l0 times the eq. 11 operator
// restricted to their line of centres (Monaghan's artificial viscosity in MPS form; not in the
// paper, pairwise antisymmetric so momentum is kept).
template <int D> void BasicEmpsFluid<D>::viscosity() {
  Timer<D> timer(times_.viscosity, times_, *decomposition_);
  ParticleSet& p = particles_;
  const std::size_t n = owned();
  const double c_lap = 2.0 * D / (lambda0_ * n0_);
  const double nu = options_.viscosity, mu_V = options_.density * nu * options_.volume();
  const double nu_art = options_.artificial_viscosity * options_.sound_speed * options_.l0;
  const WallContactOptions& contact = options_.wall.contact;
  const double nu_wall = contact.model == WallContact::viscous
                             ? contact.viscosity * options_.sound_speed * options_.l0
                             : 0.0;
  const double nu_approach =
      options_.wall.mirror.approach_viscosity * options_.sound_speed * options_.l0;
  const bool approach = nu_approach > 0;
  const double rho_V = options_.density * options_.volume();
  const Coords<D> x = p.position.coords(), v = p.velocity.coords();
  scratch_.resize(D * n);
  double* out = scratch_.data();
  std::array<std::array<double*, 2>, erp::max_faces> f_wall{}; // walls_.viscous (2-D)
  const bool viscous_walls = nu > 0 || approach;
  if constexpr (D == 2)
    for (std::size_t k = 0; k < erp::max_faces; ++k) f_wall[k] = components(walls_.viscous[k]);
  else // the viscous slots of eq. 52, empty without a viscous wall term
    for (std::size_t k = 0; k < max_faces3; ++k)
      walls_.forces[viscous_slot3 + k].resize(viscous_walls ? n : 0);
  // The closing-pair sum only when alpha > 0.
  // near_wall: its part on pairs with a particle within r_e of a wall (WallContact::viscous).
  const auto sweep = [&](auto artificial, auto near_wall) {
    parallel_for_balanced(n, [&](std::size_t i) {
      VecSum<D> v_i, s{}, a_art{}, b{};
      for (std::size_t a = 0; a < D; ++a) v_i[a] = v[a][i];
      if constexpr (!decltype(artificial)::value) { // eq. 11's fluid part alone (pair_sums)
        s = laplacian_sum<D>(pair_row(i), x, v, v_i, options_.vector_kernels);
      } else if constexpr (!decltype(near_wall)::value) { // and the closing pairs' (pair_sums)
        const ViscousSum<D> sum = viscous_sum<D>(pair_row(i), x, v, v_i, options_.vector_kernels);
        s = sum.laplacian, a_art = sum.closing;
      } else if constexpr (D == 2) { // and the closing pairs' part near a wall apart (2-D)
        const std::vector<int>& nearest = walls_.hits.face[0].segment;
        const double xi = p.x[i], yi = p.y[i], vxi = v_i[0], vyi = v_i[1];
        const bool wall_i = nearest[i] >= 0;
        const std::uint32_t* row = neighbours_.row(i);
        for (std::uint32_t k = 0, c = neighbours_.count(i); k < c; ++k) {
          const std::uint32_t j = row[k];
          const double dx = p.x[j] - xi, dy = p.y[j] - yi, r2 = dx * dx + dy * dy;
          if (r2 >= re2_) continue;
          const double w = w_e_.inside(std::sqrt(r2));
          const double dvx = p.vx[j] - vxi, dvy = p.vy[j] - vyi;
          s[0] += dvx * w;
          s[1] += dvy * w;
          const double closing = dvx * dx + dvy * dy; // < 0: the pair closes in
          if (closing < 0 && r2 > 0) {
            const double f = closing * w / r2; // ((v_j - v_i) . e) e w
            a_art[0] += f * dx;
            a_art[1] += f * dy;
            if (wall_i || nearest[j] >= 0) b[0] += f * dx, b[1] += f * dy;
          }
        }
      }
      VecSum<D> lap, a_wall3{};
      for (std::size_t a = 0; a < D; ++a) lap[a] = c_lap * s[a];
      // The wall's part on each face (eq. 24, the approach viscosity; 2-D).
      std::array<Vec2, erp::max_faces> m, a_wall;
      if constexpr (D == 2) {
        m.fill(Vec2::Zero());
        a_wall.fill(Vec2::Zero());
        for (std::size_t k = 0; k < erp::max_faces; ++k) {
          if (!(viscous_walls && walls_.hits.face[k].segment[i] >= 0)) continue;
          const MirrorViscous mirror = walls_.terms.mirror_viscous(i, k, approach);
          m[k] = c_lap * mirror.laplacian;
          a_wall[k] = nu_approach * c_lap * mirror.approach;
        }
        for (const Vec2& mk : m) lap[0] += mk.x(), lap[1] += mk.y();
      } else if (viscous_walls) { // 3-D: each face's eq. 24 term and approach viscosity, added
        for (std::size_t k = 0; k < max_faces3; ++k) { // to the particle, its force recorded
          Vec3 a_k = Vec3::Zero();
          if (walls_.hits[k].triangle[i] >= 0) {
            const MirrorViscous3 mirror = walls_.terms.mirror_viscous(i, k, approach);
            a_k = c_lap * (nu * mirror.laplacian + nu_approach * mirror.approach);
            for (std::size_t a = 0; a < D; ++a) a_wall3[a] += a_k[static_cast<Eigen::Index>(a)];
          }
          walls_.terms.record_viscous(i, k, rho_V * a_k, walls_.forces); // eq. 52
        }
      }
      for (std::size_t a = 0; a < D; ++a) {
        out[D * i + a] = nu * lap[a];
        if constexpr (decltype(artificial)::value) out[D * i + a] += nu_art * c_lap * a_art[a];
        if constexpr (decltype(near_wall)::value) out[D * i + a] += nu_wall * c_lap * b[a];
        if constexpr (D == 3) out[D * i + a] += a_wall3[a];
      }
      if constexpr (D == 2) {
        for (std::size_t k = 0; k < erp::max_faces; ++k) { // V_i mu R <lap v>_i' (eq. 52)
          f_wall[k][0][i] = mu_V * m[k].x();
          f_wall[k][1][i] = mu_V * m[k].y();
        }
        if (approach) {
          Vec2 a_sum = a_wall[0];
          for (std::size_t k = 1; k < erp::max_faces; ++k) a_sum += a_wall[k];
          out[2 * i] += a_sum.x();
          out[2 * i + 1] += a_sum.y();
          for (std::size_t k = 0; k < erp::max_faces; ++k) {
            f_wall[k][0][i] += rho_V * a_wall[k].x();
            f_wall[k][1][i] += rho_V * a_wall[k].y();
          }
        }
      }
    });
  };
  if constexpr (D == 2)
    if (nu_wall > 0) return sweep(std::true_type{}, std::true_type{});
  if (nu_art > 0)
    sweep(std::true_type{}, std::false_type{});
  else
    sweep(std::false_type{}, std::false_type{});
}

template void BasicEmpsFluid<2>::viscosity();
template void BasicEmpsFluid<3>::viscosity();

} // namespace fsi::emps
