// The viscous part of the EMPS step's first stage (eqs. 11, 13, 24) and the closing-pair
// viscosities.
#include "fluid_emps/emps_fluid.hpp"
#include "fsi/core/parallel.hpp"
#include "step_timer.hpp"

#include <array>
#include <cmath>
#include <type_traits>

namespace fsi::emps {

// nu <lap v>^ERP into scratch_ (eqs. 11, 24; advance adds it and g to v, eq. 13); visc_wall_
// keeps each face's viscous wall force (with wall_approach_viscosity alpha_w, also alpha_w c l0
// times the mirror closing-pair sum of WallTerms::mirror_viscous, a wall force).
// With artificial_viscosity alpha, closing pairs also feel alpha c l0 times the eq. 11 operator
// restricted to their line of centres (Monaghan's artificial viscosity in MPS form; not in the
// paper, pairwise antisymmetric so momentum is kept).
void EmpsFluid::viscosity() {
  Timer timer(times_.viscosity);
  Particles& p = particles_;
  const std::size_t n = p.size();
  const double c_lap = 2.0 * dim / (lambda0_ * n0_);
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
  const std::vector<int>& nearest = hits_.face[0].segment;
  scratch_.resize(2 * n);
  // The closing-pair sum only when alpha > 0.
  // near_wall: its part on pairs with a particle within r_e of a wall (WallContact::viscous).
  const auto sweep = [&](auto artificial, auto near_wall) {
    parallel_for_balanced(n, [&](std::size_t i) {
      const double xi = p.x[i], yi = p.y[i], vxi = p.vx[i], vyi = p.vy[i];
      double sx = 0, sy = 0, ax = 0, ay = 0, bx = 0, by = 0;
      if constexpr (!decltype(artificial)::value) { // eq. 11's fluid part alone (pair_sums)
        const VecSum lap = laplacian_sum(pair_row(i), p.x.data(), p.y.data(), p.vx.data(),
                                         p.vy.data(), vxi, vyi, options_.vector_kernels);
        sx = lap.x, sy = lap.y;
      } else if constexpr (!decltype(near_wall)::value) { // and the closing pairs' (pair_sums)
        const ViscousSum v = viscous_sum(pair_row(i), p.x.data(), p.y.data(), p.vx.data(),
                                         p.vy.data(), vxi, vyi, options_.vector_kernels);
        sx = v.laplacian.x, sy = v.laplacian.y, ax = v.closing.x, ay = v.closing.y;
      } else { // and the closing pairs' part near a wall apart (WallContact::viscous)
        const bool wall_i = nearest[i] >= 0;
        const std::uint32_t* row = neighbours_.row(i);
        for (std::uint32_t k = 0, c = neighbours_.count(i); k < c; ++k) {
          const std::uint32_t j = row[k];
          const double dx = p.x[j] - xi, dy = p.y[j] - yi, r2 = dx * dx + dy * dy;
          if (r2 >= re2_) continue;
          const double w = w_e_.inside(std::sqrt(r2));
          const double dvx = p.vx[j] - vxi, dvy = p.vy[j] - vyi;
          sx += dvx * w;
          sy += dvy * w;
          const double closing = dvx * dx + dvy * dy; // < 0: the pair closes in
          if (closing < 0 && r2 > 0) {
            const double s = closing * w / r2; // ((v_j - v_i) . e) e w
            ax += s * dx;
            ay += s * dy;
            if (wall_i || nearest[j] >= 0) bx += s * dx, by += s * dy;
          }
        }
      }
      // The wall's part on each face (eq. 24, the approach viscosity).
      std::array<Vec2, erp::max_faces> m, a;
      m.fill(Vec2::Zero());
      a.fill(Vec2::Zero());
      for (std::size_t k = 0; k < erp::max_faces; ++k) {
        if (!((nu > 0 || approach) && hits_.face[k].segment[i] >= 0)) continue;
        const MirrorViscous mirror = walls_.mirror_viscous(i, k, approach);
        m[k] = c_lap * mirror.laplacian;
        a[k] = nu_approach * c_lap * mirror.approach;
      }
      double lx = c_lap * sx, ly = c_lap * sy;
      for (const Vec2& mk : m) lx += mk.x(), ly += mk.y();
      scratch_[2 * i] = nu * lx;
      scratch_[2 * i + 1] = nu * ly;
      if constexpr (decltype(artificial)::value) {
        scratch_[2 * i] += nu_art * c_lap * ax;
        scratch_[2 * i + 1] += nu_art * c_lap * ay;
      }
      if constexpr (decltype(near_wall)::value) {
        scratch_[2 * i] += nu_wall * c_lap * bx;
        scratch_[2 * i + 1] += nu_wall * c_lap * by;
      }
      for (std::size_t k = 0; k < erp::max_faces; ++k)
        visc_wall_[k][i] = mu_V * m[k]; // V_i mu R <lap v>_i' (eq. 52, viscous wall part)
      if (approach) {
        Vec2 a_sum = a[0];
        for (std::size_t k = 1; k < erp::max_faces; ++k) a_sum += a[k];
        scratch_[2 * i] += a_sum.x();
        scratch_[2 * i + 1] += a_sum.y();
        for (std::size_t k = 0; k < erp::max_faces; ++k) visc_wall_[k][i] += rho_V * a[k];
      }
    });
  };
  if (nu_wall > 0)
    sweep(std::true_type{}, std::true_type{});
  else if (nu_art > 0)
    sweep(std::true_type{}, std::false_type{});
  else
    sweep(std::false_type{}, std::false_type{});
}

} // namespace fsi::emps
