// The EMPS step's second stage: pnd and pressure (eqs. 9, 15, 17, 20) and the pressure gradient
// with the walls' parts and their forces (eqs. 10, 14, 25-27, 52).
#include "fluid_emps/emps_fluid.hpp"
#include "fsi/core/parallel.hpp"
#include "step_timer.hpp"

#include <array>
#include <cmath>

namespace fsi::emps {

// n*_i = sum_j w_ij + the wall part (eqs. 9, 20; WallTerms::pnd, SpaceWallTerms::pnd); p_i = c^2
// rho/n0 (n*_i - n0), 0 on the free surface n*_i < beta n0 (eqs. 15, 17).
template <int D> void BasicEmpsFluid<D>::density_and_pressure() {
  Timer<D> timer(times_.density, times_, *decomposition_);
  ParticleSet& p = particles_;
  const std::size_t n = owned();
  const double stiffness = options_.sound_speed * options_.sound_speed * options_.density / n0_;
  const double surface = options_.beta * n0_;
  const Coords<D> x = p.position.coords();
  const std::size_t pairs = parallel_reduce_balanced(
      n, std::size_t{0},
      [&](std::size_t i) {
        const PndSum sum = pnd_sum<D>(pair_row(i), x, options_.vector_kernels);
        double pnd = sum.pnd;
        pnd = walls_.terms.pnd(i, sum.pnd);
        p.pnd[i] = pnd;
        const bool free = pnd < surface;
        p.surface[i] = free;
        p.p[i] = free ? 0.0 : stiffness * (pnd - n0_);
        return std::size_t{sum.within};
      },
      [](std::size_t a, std::size_t b) { return a + b; });
  // The gradient's p_j (eqs. 10, 26); pnd and surface are read at owned rows only.
  decomposition_->update_ghosts(p.fields, particles::FieldList(p.p));
  const double all_pairs = decomposition_->sum(static_cast<double>(pairs));
  const double all_n = decomposition_->sum(static_cast<double>(n));
  mean_neighbours_ = all_n > 0 ? all_pairs / all_n : 0.0;
}

template <int D>
WallForceParts BasicEmpsFluid<D>::wall_force_parts(int first, int last) const requires(D == 2) {
  WallForceParts out;
  for (std::size_t i = 0; i < walls_.forces.size(); ++i)
    for (const FaceForces& f : walls_.forces.face) {
      if (f.segment[i] < first || f.segment[i] >= last) continue;
      out.pressure -= f.f[i] - f.f_contact[i] - f.f_viscous[i];
      out.repulsive -= f.f_contact[i];
      out.viscous -= f.f_viscous[i];
    }
  return out;
}

// Fluid-fluid part of <grad p>_i (eq. 10) without the d/n0 factor: sum over the neighbours of
// (p_j + p_i) (x_j - x_i) / r_ij^2 w_ij; with `shepard` (2-D, for the walls), also the
// neighbours' mean pressure sum p_j w_ij / sum w_ij into it (0 without neighbours).
template <int D> VecSum<D> BasicEmpsFluid<D>::fluid_gradient(std::size_t i, double* shepard) const {
  const ParticleSet& p = particles_;
  const double p_i = p.p[i];
  if (!shepard)
    return gradient_sum<D>(pair_row(i), p.position.coords(), p.p.data(), p_i,
                           options_.vector_kernels);
  const double xi = p.x[i], yi = p.y[i];
  double gx = 0, gy = 0, pw = 0, ws = 0;
  const std::uint32_t* row = neighbours_.row(i);
  for (std::uint32_t k = 0, c = neighbours_.count(i); k < c; ++k) {
    const std::uint32_t j = row[k];
    const double dx = p.x[j] - xi, dy = p.y[j] - yi, r2 = dx * dx + dy * dy;
    if (r2 >= re2_ || r2 == 0.0) continue;
    const double w = w_e_.inside(std::sqrt(r2));
    const double s = (p.p[j] + p_i) * w / r2;
    gx += s * dx;
    gy += s * dy;
    pw += p.p[j] * w, ws += w;
  }
  *shepard = ws > 0 ? pw / ws : 0.0;
  return {gx, gy};
}

// v^{n+1} = v* - dt/rho <grad p>^ERP, x^{n+1} = x* + dt (v^{n+1} - v*) (eqs. 10, 14, 25-27),
// and the wall force of eq. 52 on each face (the viscous part: the viscous stage's, in 2-D added
// to it here, in 3-D in slots of its own).
template <int D> void BasicEmpsFluid<D>::pressure_gradient(double dt) {
  Timer<D> timer(times_.pressure_gradient, times_, *decomposition_);
  ParticleSet& p = particles_;
  const std::size_t n = owned();
  const double c_grad = D / n0_;
  const double inv_rho = 1.0 / options_.density, V = options_.volume();
  const bool neighbours = options_.wall.mirror.pressure == WallPressure::neighbours;
  scratch_.resize(D * n);
  double* dx = scratch_.data();
  const std::array<double*, D> v = components(p.velocity);
  std::array<std::array<double*, 2>, erp::max_faces> f_wall{}; // walls_.viscous (2-D)
  if constexpr (D == 2) {
    walls_.forces.resize(n);
    for (std::size_t k = 0; k < erp::max_faces; ++k) f_wall[k] = components(walls_.viscous[k]);
  } else {
    for (std::size_t k = 0; k < pressure_slots3; ++k) // the pieces' with convex_corners only
      walls_.forces[k].resize(k < max_faces3 || walls_.convex_corners ? n : 0);
  }
  parallel_for_balanced(n, [&](std::size_t i) {
    VecD<D> grad;
    if constexpr (D == 2) {
      // p_i' (eq. 26, or WallPressure::neighbours for a free-surface particle at a wall)
      const erp::WallHits& hits = walls_.hits;
      double p_mirror = p.p[i];
      const bool mean = neighbours && p.surface[i] && hits.face[0].segment[i] >= 0;
      const VecSum<2> fluid = fluid_gradient(i, mean ? &p_mirror : nullptr);
      // Each face's wall part of <grad p>_i: the mirror pressure term and the contact term.
      std::array<Vec2, erp::max_faces> wall, contact;
      wall.fill(Vec2::Zero());
      contact.fill(Vec2::Zero());
      for (std::size_t k = 0; k < erp::max_faces; ++k) {
        if (hits.face[k].segment[i] < 0) continue;
        contact[k] = walls_.terms.contact(i, k, dt);
        wall[k] = walls_.terms.mirror_pressure(i, k, p_mirror) + contact[k];
      }
      grad = c_grad * Vec2(fluid[0], fluid[1]);
      for (const Vec2& wk : wall) grad += wk;
      // eq. 52: f_wall = V (-(R_ref <grad p>_i' + f_rep) + mu R <lap v>_i'), per face
      for (std::size_t k = 0; k < erp::max_faces; ++k) {
        const erp::FaceHits& h = hits.face[k];
        FaceForces& f = walls_.forces.face[k];
        const int s = h.segment[i];
        const Vec2 visc = s >= 0 ? Vec2(f_wall[k][0][i], f_wall[k][1][i]) : Vec2::Zero();
        f.segment[i] = s;
        f.t[i] = s >= 0 ? h.t[i] : 0.0;
        f.x_wall[i] = s >= 0 ? h.x_wall[i] : Vec2::Zero();
        f.f[i] = s >= 0 ? Vec2(-V * wall[k] + visc) : Vec2::Zero();
        f.f_contact[i] = -V * contact[k];
        f.f_viscous[i] = visc;
      }
    } else { // 3-D: the wall terms over the faces (SpaceWallTerms::add_pressure)
      const VecSum<D> fluid = fluid_gradient(i, nullptr);
      for (int a = 0; a < D; ++a) grad[a] = c_grad * fluid[static_cast<std::size_t>(a)];
      WallShares3 wall;
      walls_.terms.add_pressure(i, dt, grad, wall);
      walls_.terms.record_forces(i, wall, V, walls_.forces); // eq. 52, per face and piece
    }
    const VecD<D> dv = -dt * inv_rho * grad;
    for (std::size_t a = 0; a < D; ++a) {
      v[a][i] += dv[static_cast<Eigen::Index>(a)];
      dx[D * i + a] = dt * dv[static_cast<Eigen::Index>(a)];
    }
  });
  const std::array<double*, D> x = components(p.position);
  parallel_for(n, [&](std::size_t i) {
    for (std::size_t a = 0; a < D; ++a) x[a][i] += dx[D * i + a];
  });
}

template <int D> const WallForces& BasicEmpsFluid<D>::wall_forces() const requires(D == 2) {
  return walls_.forces;
}

template <int D> const WallForces3& BasicEmpsFluid<D>::triangle_forces() const requires(D == 3) {
  return walls_.forces;
}

template const WallForces& BasicEmpsFluid<2>::wall_forces() const;
template const WallForces3& BasicEmpsFluid<3>::triangle_forces() const;
template WallForceParts BasicEmpsFluid<2>::wall_force_parts(int, int) const;
template void BasicEmpsFluid<2>::density_and_pressure();
template void BasicEmpsFluid<3>::density_and_pressure();
template void BasicEmpsFluid<2>::pressure_gradient(double);
template void BasicEmpsFluid<3>::pressure_gradient(double);

} // namespace fsi::emps
