// The EMPS step's second stage: pnd and pressure (eqs. 9, 15, 17, 20) and the pressure gradient
// with the walls' parts and their forces (eqs. 10, 14, 25-27, 52).
#include "fluid_emps/emps_fluid.hpp"
#include "fsi/core/parallel.hpp"
#include "step_timer.hpp"

#include <array>
#include <cmath>

namespace fsi::emps {

// n*_i = sum_j w_ij + the wall part (eqs. 9, 20; WallTerms::pnd); p_i = c^2 rho/n0 (n*_i - n0),
// 0 on the free surface n*_i < beta n0 (eqs. 15, 17).
void EmpsFluid::density_and_pressure() {
  Timer timer(times_.density);
  Particles& p = particles_;
  const std::size_t n = p.size();
  const double stiffness = options_.sound_speed * options_.sound_speed * options_.density / n0_;
  const double surface = options_.beta * n0_;
  const std::size_t pairs = parallel_reduce_balanced(
      n, std::size_t{0},
      [&](std::size_t i) {
        const PndSum sum = pnd_sum(pair_row(i), p.x.data(), p.y.data(), options_.vector_kernels);
        const double pnd = walls_.pnd(i, sum.pnd);
        p.pnd[i] = pnd;
        const bool free = pnd < surface;
        p.surface[i] = free;
        p.p[i] = free ? 0.0 : stiffness * (pnd - n0_);
        return std::size_t{sum.within};
      },
      [](std::size_t a, std::size_t b) { return a + b; });
  mean_neighbours_ = n ? static_cast<double>(pairs) / static_cast<double>(n) : 0.0;
}

WallForceParts EmpsFluid::wall_force_parts(int first, int last) const {
  WallForceParts out;
  for (std::size_t i = 0; i < wall_forces_.size(); ++i)
    for (const FaceForces& f : wall_forces_.face) {
      if (f.segment[i] < first || f.segment[i] >= last) continue;
      out.pressure -= f.f[i] - f.f_contact[i] - f.f_viscous[i];
      out.repulsive -= f.f_contact[i];
      out.viscous -= f.f_viscous[i];
    }
  return out;
}

// Fluid-fluid part of <grad p>_i (eq. 10) without the d/n0 factor: sum over the neighbours of
// (p_j + p_i) (x_j - x_i) / r_ij^2 w_ij; with `shepard`, also the neighbours' mean pressure
// sum p_j w_ij / sum w_ij into it (0 without neighbours).
Vec2 EmpsFluid::fluid_gradient(std::size_t i, double* shepard) const {
  const Particles& p = particles_;
  const double xi = p.x[i], yi = p.y[i], p_i = p.p[i];
  if (!shepard) {
    const VecSum g =
        gradient_sum(pair_row(i), p.x.data(), p.y.data(), p.p.data(), p_i, options_.vector_kernels);
    return Vec2(g.x, g.y);
  }
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
  return Vec2(gx, gy);
}

// v^{n+1} = v* - dt/rho <grad p>^ERP, x^{n+1} = x* + dt (v^{n+1} - v*) (eqs. 10, 14, 25-27),
// and the wall force of eq. 52 on each face.
void EmpsFluid::pressure_gradient(double dt) {
  Timer timer(times_.pressure_gradient);
  Particles& p = particles_;
  const std::size_t n = p.size();
  const double c_grad = dim / n0_;
  const double inv_rho = 1.0 / options_.density, V = options_.volume();
  const bool neighbours = options_.wall.mirror.pressure == WallPressure::neighbours;
  scratch_.resize(2 * n);
  parallel_for_balanced(n, [&](std::size_t i) {
    // p_i' (eq. 26, or WallPressure::neighbours for a free-surface particle at a wall)
    double p_mirror = p.p[i];
    const bool mean = neighbours && p.surface[i] && hits_.face[0].segment[i] >= 0;
    const Vec2 fluid = fluid_gradient(i, mean ? &p_mirror : nullptr);
    // Each face's wall part of <grad p>_i: the mirror pressure term and the contact term.
    std::array<Vec2, erp::max_faces> wall, contact;
    wall.fill(Vec2::Zero());
    contact.fill(Vec2::Zero());
    for (std::size_t k = 0; k < erp::max_faces; ++k) {
      if (hits_.face[k].segment[i] < 0) continue;
      contact[k] = walls_.contact(i, k, dt);
      wall[k] = walls_.mirror_pressure(i, k, p_mirror) + contact[k];
    }
    Vec2 grad = c_grad * fluid;
    for (const Vec2& wk : wall) grad += wk;
    const Vec2 dv = -dt * inv_rho * grad;
    p.vx[i] += dv.x();
    p.vy[i] += dv.y();
    scratch_[2 * i] = dt * dv.x();
    scratch_[2 * i + 1] = dt * dv.y();
    // eq. 52: f_wall = V (-(R_ref <grad p>_i' + f_rep) + mu R <lap v>_i'), per face
    for (std::size_t k = 0; k < erp::max_faces; ++k) {
      const erp::FaceHits& h = hits_.face[k];
      FaceForces& f = wall_forces_.face[k];
      const int s = h.segment[i];
      f.segment[i] = s;
      f.t[i] = s >= 0 ? h.t[i] : 0.0;
      f.x_wall[i] = s >= 0 ? h.x_wall[i] : Vec2::Zero();
      f.f[i] = s >= 0 ? Vec2(-V * wall[k] + visc_wall_[k][i]) : Vec2::Zero();
      f.f_contact[i] = -V * contact[k];
      f.f_viscous[i] = s >= 0 ? visc_wall_[k][i] : Vec2::Zero();
    }
  });
  parallel_for(n, [&](std::size_t i) {
    p.x[i] += scratch_[2 * i];
    p.y[i] += scratch_[2 * i + 1];
  });
}

} // namespace fsi::emps
