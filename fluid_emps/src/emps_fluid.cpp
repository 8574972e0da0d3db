#include "fluid_emps/emps_fluid.hpp"

#include "fsi/core/error.hpp"
#include "fsi/core/parallel.hpp"
#include "fsi/core/state_archive.hpp"
#include "geometry_erp/convex_corner.hpp"
#include "geometry_erp/mirror.hpp"
#include "particles/kernels.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <type_traits>

namespace fsi::emps {

namespace {

constexpr double dim = 2.0; // d of eqs. 10-11, the number of dimensions
constexpr std::size_t none = std::numeric_limits<std::size_t>::max();

std::size_t first_index(std::size_t n, const auto& bad) {
  return parallel_reduce_balanced(
      n, none, [&](std::size_t i) { return bad(i) ? i : none; },
      [](std::size_t a, std::size_t b) { return std::min(a, b); });
}

std::string where(const Particles& p, std::size_t i, long step, double t) {
  std::ostringstream out;
  out << "particle " << p.id[i] << " at (" << p.x[i] << ", " << p.y[i] << ") m, step " << step
      << ", t = " << t << " s";
  return out.str();
}

class Timer {
public:
  explicit Timer(double& sink) : sink_(sink), start_(wall_time()) {}
  ~Timer() { sink_ += wall_time() - start_; }
  Timer(const Timer&) = delete;
  Timer& operator=(const Timer&) = delete;

private:
  double& sink_;
  double start_;
};

void validate(const FluidOptions& o) {
  auto fail = [](const std::string& what) { throw InputError("fluid: " + what); };
  if (!(o.density > 0)) fail("density must be > 0");
  if (!(o.l0 > 0)) fail("l0 must be > 0");
  if (!(o.sound_speed > 0)) fail("sound_speed must be > 0");
  if (!(o.viscosity >= 0)) fail("viscosity must be >= 0");
  if (!(o.re_over_l0 >= 1.5)) fail("re_over_l0 must be >= 1.5");
  if (!(o.domain_max.x() > o.domain_min.x() && o.domain_max.y() > o.domain_min.y()))
    fail("the domain box is empty");
  if (!(o.skin > 0 && o.skin < 1)) fail("skin must be in (0, 1)");
  if (!(o.wall_damping >= 0)) fail("wall_damping must be >= 0");
  if (!(o.wall_viscosity >= 0)) fail("wall_viscosity must be >= 0");
  if (!(o.wall_approach_viscosity >= 0)) fail("wall_approach_viscosity must be >= 0");
}

} // namespace

EmpsFluid::EmpsFluid(const FluidOptions& options, const std::vector<Vec2>& positions,
                     erp::WallSet& walls)
    : options_((validate(options), options)),
      locator_(erp::make_wall_locator(walls, options.r_e())),
      z_(options.l0, options.r_e(), particles::MpsWeight(options.r_e())), r_e_(options.r_e()),
      n0_(erp::lattice_n0(options.l0, r_e_, particles::MpsWeight(r_e_))),
      lambda0_(erp::lattice_lambda0(options.l0, r_e_, particles::MpsWeight(r_e_))), w_e_(r_e_),
      re2_(r_e_ * r_e_),
      grid_(options.domain_min, options.domain_max, r_e_ * (1.0 + options.skin)) {
  locator_->set_second_face(options.corner_faces);
  const std::size_t n = positions.size();
  particles_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    particles_.x[i] = positions[i].x();
    particles_.y[i] = positions[i].y();
    particles_.id[i] = static_cast<std::uint32_t>(i);
  }
  const double reach = (1.0 + options.skin) * options.re_over_l0;
  capacity_ = static_cast<std::size_t>(std::ceil(2.0 * M_PI * reach * reach)) + 16;
  remove_outside();
  // pnd, pressure and free-surface flags of the initial state (for output at t = 0).
  refresh_neighbours(true, 0, 0.0);
  query_walls();
  density_and_pressure();
}

EmpsFluid::~EmpsFluid() = default;

// Initial damping phase (quiet hydrostatic starts): v <- v exp(-kappa dt) with a rate
// kappa = 20/T_d (1 - t/T_d) that fades to zero at T_d, so the run continues undamped.
void EmpsFluid::damp(double t, double dt) {
  const double T = options_.damping_time;
  if (T <= 0 || t >= T) return;
  const double factor = std::exp(-20.0 / T * (1.0 - t / T) * dt);
  Particles& p = particles_;
  parallel_for(p.size(), [&](std::size_t i) {
    p.vx[i] *= factor;
    p.vy[i] *= factor;
  });
}

void EmpsFluid::refresh_neighbours(bool allow_reorder, long step, double t) {
  Timer timer(times_.neighbours);
  Particles& p = particles_;
  const std::size_t n = p.size();
  if (neighbours_.valid(p.x.data(), p.y.data(), n, 0.5 * options_.skin * r_e_)) return;
  grid_.bin(p.x.data(), p.y.data(), n);
  if (allow_reorder && builds_ % std::max(1, options_.reorder_interval) == 0) {
    p.permute(grid_.order(), scratch_);
    ++layout_;
    grid_.bin(p.x.data(), p.y.data(), n);
  }
  ++builds_;
  if (!neighbours_.build(grid_, p.x.data(), p.y.data(), n, r_e_ * (1.0 + options_.skin), capacity_,
                         options_.vector_kernels))
    throw RunError("fluid: more than " + std::to_string(capacity_) + " neighbours at " +
                   where(p, neighbours_.overflow(), step, t) +
                   " (particles clustered: the step is likely unstable)");
}

void EmpsFluid::query_walls() {
  Timer timer(times_.walls);
  locator_->query(std::span<const double>(particles_.x), std::span<const double>(particles_.y),
                  hits_);
  hits_layout_ = layout_;
}

// With mirror_same_side: j lies behind the wall of the hit (x_wall, n_wall), on the far side of a
// thin wall, so the mirror sums leave it out (its image would land on the particle's side).
bool EmpsFluid::behind(std::uint32_t j, const Vec2& x_wall, const Vec2& n_wall) const {
  return options_.mirror_same_side &&
         (particles_.x[j] - x_wall.x()) * n_wall.x() + (particles_.y[j] - x_wall.y()) * n_wall.y() <
             0.0;
}

// At the mirror point x_i' = 2 x_wall - x_i (eq. 23), over the real neighbours of x_i' (j = i
// included), without the 2d/(lambda0 n0) factor:
// - laplacian: <lap v>_i' with the mirror velocity v_i' (eq. 24 no-slip, or slip), turned back by
//   R_inv (no-slip) or R_ref (slip);
// - approach (with `approach`): the closing-pair sum of the pairs (i, ghost of j) that close in
//   across the wall. The ghost of j sits at the reflection of x_j and moves with v_wall +
//   R_ref (v_j - v_wall); R_ref maps x_j - x_i' to the pair's separation and v_j - v_i^s to its
//   relative velocity (v_i^s: i's slip mirror velocity), so the sum is R_ref sum over closing
//   pairs of ((v_j - v_i^s) . e) e w, e and r those of x_j - x_i' (as the fluid's closing pairs).
EmpsFluid::MirrorViscous EmpsFluid::mirror_viscous(std::size_t i, const Vec2& x_wall,
                                                   const Vec2& n_wall, const Vec2& v_wall,
                                                   bool approach) const {
  const Particles& p = particles_;
  const bool no_slip = options_.wall_condition == WallCondition::no_slip;
  const Vec2 v_i(p.vx[i], p.vy[i]);
  const Vec2 v_m = no_slip ? erp::mirror_velocity_no_slip(v_i, v_wall, n_wall)
                           : erp::mirror_velocity_slip(v_i, v_wall, n_wall);
  const Vec2 v_s = erp::mirror_velocity_slip(v_i, v_wall, n_wall);
  const double mpx = 2.0 * x_wall.x() - p.x[i], mpy = 2.0 * x_wall.y() - p.y[i];
  double ux = 0, uy = 0, ax = 0, ay = 0;
  grid_.for_each_near(mpx, mpy, [&](std::uint32_t j) {
    const double dx = p.x[j] - mpx, dy = p.y[j] - mpy, r2 = dx * dx + dy * dy;
    if (r2 >= re2_ || behind(j, x_wall, n_wall)) return;
    const double w = w_e_.inside(std::sqrt(r2));
    ux += (p.vx[j] - v_m.x()) * w;
    uy += (p.vy[j] - v_m.y()) * w;
    if (!approach || r2 == 0.0) return;
    const double closing = (p.vx[j] - v_s.x()) * dx + (p.vy[j] - v_s.y()) * dy;
    if (closing >= 0) return;
    ax += closing * w / r2 * dx;
    ay += closing * w / r2 * dy;
  });
  return {(no_slip ? erp::R_inv() : erp::R_ref(n_wall)) * Vec2(ux, uy),
          erp::R_ref(n_wall) * Vec2(ax, ay)};
}

// nu <lap v>^ERP into scratch_ (eqs. 11, 24; advance adds it and g to v, eq. 13); visc_wall_
// keeps the viscous wall forces (with wall_approach_viscosity alpha_w, also alpha_w c l0 times the
// mirror closing-pair sum of mirror_viscous, a wall force).
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
  const double nu_wall = options_.wall_contact == WallContact::viscous
                             ? options_.wall_viscosity * options_.sound_speed * options_.l0
                             : 0.0;
  const double nu_approach = options_.wall_approach_viscosity * options_.sound_speed * options_.l0;
  const bool approach = nu_approach > 0;
  const double rho_V = options_.density * options_.volume();
  scratch_.resize(2 * n);
  // The closing-pair sum only when alpha > 0: it costs as much as the rest of the loop.
  // near_wall: its part on pairs with a particle within r_e of a wall (WallContact::viscous).
  const auto sweep = [&](auto artificial, auto near_wall) {
    parallel_for_balanced(n, [&](std::size_t i) {
      const double xi = p.x[i], yi = p.y[i], vxi = p.vx[i], vyi = p.vy[i];
      double sx = 0, sy = 0, ax = 0, ay = 0, bx = 0, by = 0;
      if constexpr (!decltype(artificial)::value) { // eq. 11's fluid part alone (pair_sums)
        const VecSum lap = laplacian_sum(pair_row(i), p.x.data(), p.y.data(), p.vx.data(),
                                         p.vy.data(), vxi, vyi, options_.vector_kernels);
        sx = lap.x, sy = lap.y;
      } else {
        const bool wall_i = hits_.segment[i] >= 0;
        const std::uint32_t* row = neighbours_.row(i);
        for (std::uint32_t k = 0, c = neighbours_.count(i); k < c; ++k) {
          const std::uint32_t j = row[k];
          const double dx = p.x[j] - xi, dy = p.y[j] - yi, r2 = dx * dx + dy * dy;
          if (r2 >= re2_) continue;
          const double w = w_e_.inside(std::sqrt(r2));
          const double dvx = p.vx[j] - vxi, dvy = p.vy[j] - vyi;
          sx += dvx * w;
          sy += dvy * w;
          const double approach = dvx * dx + dvy * dy; // < 0: the pair closes in
          if (approach < 0 && r2 > 0) {
            const double s = approach * w / r2; // ((v_j - v_i) . e) e w / r
            ax += s * dx;
            ay += s * dy;
            if constexpr (decltype(near_wall)::value) {
              if (wall_i || hits_.segment[j] >= 0) bx += s * dx, by += s * dy;
            }
          }
        }
      }
      Vec2 m1 = Vec2::Zero(), m2 = Vec2::Zero(), a1 = Vec2::Zero(), a2 = Vec2::Zero();
      if ((nu > 0 || approach) && hits_.segment[i] >= 0) {
        const MirrorViscous m =
            mirror_viscous(i, hits_.x_wall[i], hits_.n_wall[i], hits_.v_wall[i], approach);
        m1 = c_lap * m.laplacian;
        a1 = nu_approach * c_lap * m.approach;
      }
      if ((nu > 0 || approach) && hits_.segment2[i] >= 0) {
        const MirrorViscous m =
            mirror_viscous(i, hits_.x_wall2[i], hits_.n_wall2[i], hits_.v_wall2[i], approach);
        m2 = c_lap * m.laplacian;
        a2 = nu_approach * c_lap * m.approach;
      }
      scratch_[2 * i] = nu * (c_lap * sx + m1.x() + m2.x());
      scratch_[2 * i + 1] = nu * (c_lap * sy + m1.y() + m2.y());
      if constexpr (decltype(artificial)::value) {
        scratch_[2 * i] += nu_art * c_lap * ax;
        scratch_[2 * i + 1] += nu_art * c_lap * ay;
      }
      if constexpr (decltype(near_wall)::value) {
        scratch_[2 * i] += nu_wall * c_lap * bx;
        scratch_[2 * i + 1] += nu_wall * c_lap * by;
      }
      visc_wall_[i] = mu_V * m1; // V_i mu R <lap v>_i' (eq. 52, viscous wall part)
      visc_wall2_[i] = mu_V * m2;
      if (approach) {
        scratch_[2 * i] += a1.x() + a2.x();
        scratch_[2 * i + 1] += a1.y() + a2.y();
        visc_wall_[i] += rho_V * a1;
        visc_wall2_[i] += rho_V * a2;
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

// n*_i = sum_j w_ij + z(r_wall,i) (eqs. 9, 20; or scaled, see WallDensity); p_i = c^2 rho/n0 (n*_i
// - n0), 0 on the free surface n*_i < beta n0 (eqs. 15, 17).
void EmpsFluid::density_and_pressure() {
  Timer timer(times_.density);
  Particles& p = particles_;
  const std::size_t n = p.size();
  const double stiffness = options_.sound_speed * options_.sound_speed * options_.density / n0_;
  const double surface = options_.beta * n0_;
  const bool scaled = options_.wall_density == WallDensity::scaled;
  const bool convex = options_.convex_corners;
  const std::size_t pairs = parallel_reduce_balanced(
      n, std::size_t{0},
      [&](std::size_t i) {
        const PndSum sum = pnd_sum(pair_row(i), p.x.data(), p.y.data(), options_.vector_kernels);
        double pnd = sum.pnd;
        double z = 0.0; // wall part (eq. 20), a corner's overlap counted once
        if (hits_.segment[i] >= 0) z += z_(hits_.r[i]);
        if (hits_.segment2[i] >= 0) z += z_(hits_.r2[i]) - corner_overlap(i);
        if (convex && hits_.segment[i] >= 0) z += convex_part(i).dz;
        pnd += scaled ? z * std::max(1.0, pnd / std::max(n0_ - z, 0.25 * n0_)) : z;
        p.pnd[i] = pnd;
        const bool free = pnd < surface;
        p.surface[i] = free;
        p.p[i] = free ? 0.0 : stiffness * (pnd - n0_);
        return std::size_t{sum.within};
      },
      [](std::size_t a, std::size_t b) { return a + b; });
  mean_neighbours_ = n ? static_cast<double>(pairs) / static_cast<double>(n) : 0.0;
}

// A concave corner's doubly counted lattice (geometry_erp concave_overlap).
double EmpsFluid::corner_overlap(std::size_t i) const {
  return erp::concave_overlap(hits_.n_wall[i], hits_.n_wall2[i], hits_.r[i], hits_.r2[i],
                              options_.l0, r_e_, w_e_);
}

// The convex corners of particle i's nearest segment (geometry_erp convex_part).
erp::ConvexPart EmpsFluid::convex_part(std::size_t i) const {
  return erp::convex_part(locator_->walls(), hits_.segment[i], hits_.t[i],
                          Vec2(particles_.x[i], particles_.y[i]), hits_.r[i], hits_.n_wall[i], z_,
                          options_.l0, r_e_, w_e_);
}

// R_ref <grad p>_i' (eqs. 25-26) without the d/n0 factor: the gradient sum at the mirror point
// over the real neighbours of x_i' (j = i included) with p_i' (p_i in eq. 26; see WallPressure),
// reflected back.
Vec2 EmpsFluid::mirror_gradient(std::size_t i, const Vec2& x_wall, const Vec2& n_wall,
                                double p_mirror) const {
  const Particles& p = particles_;
  const double p_i = p_mirror;
  const double mpx = 2.0 * x_wall.x() - p.x[i], mpy = 2.0 * x_wall.y() - p.y[i];
  double ux = 0, uy = 0;
  grid_.for_each_near(mpx, mpy, [&](std::uint32_t j) {
    const double dx = p.x[j] - mpx, dy = p.y[j] - mpy, r2 = dx * dx + dy * dy;
    if (r2 >= re2_ || r2 == 0.0 || behind(j, x_wall, n_wall)) return;
    const double s = (p.p[j] + p_i) * w_e_.inside(std::sqrt(r2)) / r2;
    ux += s * dx;
    uy += s * dy;
  });
  return erp::R_ref(n_wall) * Vec2(ux, uy);
}

// f_rep (eq. 27), in the units of grad p; r is floored at l0/2000 (a particle on the wall).
Vec2 EmpsFluid::repulsion(double r, const Vec2& n_wall) const {
  const double half_l0 = 0.5 * options_.l0;
  if (r >= half_l0) return Vec2::Zero();
  return -options_.alpha_rep * (half_l0 / std::max(r, 1e-3 * half_l0) - 1.0) * n_wall;
}

// WallContact::damped: the wall-normal approach velocity u_n = (v*_i - v_wall).n < 0 within l0
// of a wall loses the fraction 1 - exp(-gamma dt) in this step, gamma = wall_damping c/l0 (1 -
// r/l0): rho/dt (1 - exp(-gamma dt)) u_n n in the units of grad p (added to it, as f_rep).
// Separation is not resisted; the restitution of a particle stopped within l0 is that of f_rep.
Vec2 EmpsFluid::normal_damping(std::size_t i, double r, const Vec2& n_wall, const Vec2& v_wall,
                               double dt) const {
  const double l0 = options_.l0;
  if (r >= l0) return Vec2::Zero();
  const double u_n = (Vec2(particles_.vx[i], particles_.vy[i]) - v_wall).dot(n_wall);
  if (u_n >= 0.0) return Vec2::Zero();
  const double gamma = options_.wall_damping * options_.sound_speed / l0 * (1.0 - r / l0);
  return options_.density / dt * (1.0 - std::exp(-gamma * dt)) * u_n * n_wall;
}

WallForceParts EmpsFluid::wall_force_parts(int first, int last) const {
  const WallForces& w = wall_forces_;
  WallForceParts out;
  auto add = [&](int s, const Vec2& f, const Vec2& f_contact, const Vec2& f_viscous) {
    if (s < first || s >= last) return;
    out.pressure -= f - f_contact - f_viscous;
    out.repulsive -= f_contact;
    out.viscous -= f_viscous;
  };
  for (std::size_t i = 0; i < w.segment.size(); ++i) {
    add(w.segment[i], w.f[i], w.f_contact[i], w.f_viscous[i]);
    add(w.segment2[i], w.f2[i], w.f_contact2[i], w.f_viscous2[i]);
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

// Wall parts of <grad p>_i on each face: (d/n0) R_ref <grad p>_i' + f_rep (eqs. 25-27) with the
// mirror pressure p_i', the convex corners' wedge (virtual particles at p_i') in place of the
// mirror in proportion to its share, and the contact part alone (f_rep, with the damping of
// WallContact::damped).
EmpsFluid::WallGradient EmpsFluid::wall_gradient(std::size_t i, double dt, double p_mirror) const {
  const double c_grad = dim / n0_;
  const bool damped = options_.wall_contact == WallContact::damped;
  WallGradient out;
  if (hits_.segment[i] >= 0) {
    Vec2 mirror = mirror_gradient(i, hits_.x_wall[i], hits_.n_wall[i], p_mirror);
    if (options_.convex_corners) {
      const erp::ConvexPart part = convex_part(i);
      mirror = (1.0 - part.share) * mirror + part.share * (particles_.p[i] + p_mirror) * part.g;
    }
    out.contact1 = repulsion(hits_.r[i], hits_.n_wall[i]);
    if (damped) out.contact1 += normal_damping(i, hits_.r[i], hits_.n_wall[i], hits_.v_wall[i], dt);
    out.wall1 = c_grad * mirror + out.contact1;
  }
  if (hits_.segment2[i] >= 0) {
    out.contact2 = repulsion(hits_.r2[i], hits_.n_wall2[i]);
    if (damped)
      out.contact2 += normal_damping(i, hits_.r2[i], hits_.n_wall2[i], hits_.v_wall2[i], dt);
    out.wall2 =
        c_grad * mirror_gradient(i, hits_.x_wall2[i], hits_.n_wall2[i], p_mirror) + out.contact2;
  }
  return out;
}

// v^{n+1} = v* - dt/rho <grad p>^ERP, x^{n+1} = x* + dt (v^{n+1} - v*) (eqs. 10, 14, 25-27),
// and the wall force of eq. 52 on each face.
void EmpsFluid::pressure_gradient(double dt) {
  Timer timer(times_.pressure_gradient);
  Particles& p = particles_;
  const std::size_t n = p.size();
  const double c_grad = dim / n0_;
  const double inv_rho = 1.0 / options_.density, V = options_.volume();
  const bool neighbours = options_.wall_pressure == WallPressure::neighbours;
  scratch_.resize(2 * n);
  parallel_for_balanced(n, [&](std::size_t i) {
    // p_i' (eq. 26, or WallPressure::neighbours for a free-surface particle at a wall)
    double p_mirror = p.p[i];
    const bool mean = neighbours && p.surface[i] && hits_.segment[i] >= 0;
    const Vec2 fluid = fluid_gradient(i, mean ? &p_mirror : nullptr);
    const WallGradient wall = wall_gradient(i, dt, p_mirror);
    const Vec2 grad = c_grad * fluid + wall.wall1 + wall.wall2;
    const Vec2 dv = -dt * inv_rho * grad;
    p.vx[i] += dv.x();
    p.vy[i] += dv.y();
    scratch_[2 * i] = dt * dv.x();
    scratch_[2 * i + 1] = dt * dv.y();
    // eq. 52: f_wall = V (-(R_ref <grad p>_i' + f_rep) + mu R <lap v>_i'), per face
    const int s1 = hits_.segment[i], s2 = hits_.segment2[i];
    WallForces& f = wall_forces_;
    f.segment[i] = s1;
    f.t[i] = s1 >= 0 ? hits_.t[i] : 0.0;
    f.x_wall[i] = s1 >= 0 ? hits_.x_wall[i] : Vec2::Zero();
    f.f[i] = s1 >= 0 ? Vec2(-V * wall.wall1 + visc_wall_[i]) : Vec2::Zero();
    f.segment2[i] = s2;
    f.t2[i] = s2 >= 0 ? hits_.t2[i] : 0.0;
    f.x_wall2[i] = s2 >= 0 ? hits_.x_wall2[i] : Vec2::Zero();
    f.f2[i] = s2 >= 0 ? Vec2(-V * wall.wall2 + visc_wall2_[i]) : Vec2::Zero();
    f.f_contact[i] = -V * wall.contact1;
    f.f_contact2[i] = -V * wall.contact2;
    f.f_viscous[i] = s1 >= 0 ? visc_wall_[i] : Vec2::Zero();
    f.f_viscous2[i] = s2 >= 0 ? visc_wall2_[i] : Vec2::Zero();
  });
  parallel_for(n, [&](std::size_t i) {
    p.x[i] += scratch_[2 * i];
    p.y[i] += scratch_[2 * i + 1];
  });
}

void EmpsFluid::advance(double t, double dt) {
  Particles& p = particles_;
  {
    Timer timer(times_.walls);
    locator_->update();
  }
  const Vec2 g = options_.gravity;
  refresh_neighbours(true, step_ + 1, t);
  const std::size_t n = p.size();
  // The viscous loop writes every particle's viscous wall forces; without it they are zero.
  const bool viscous =
      options_.viscosity > 0 || options_.artificial_viscosity > 0 ||
      options_.wall_approach_viscosity > 0 ||
      (options_.wall_contact == WallContact::viscous && options_.wall_viscosity > 0);
  if (viscous) {
    visc_wall_.resize(n);
    visc_wall2_.resize(n);
  } else {
    visc_wall_.assign(n, Vec2::Zero());
    visc_wall2_.assign(n, Vec2::Zero());
  }
  for (auto* a : {&wall_forces_.segment, &wall_forces_.segment2}) a->resize(n);
  for (auto* a : {&wall_forces_.t, &wall_forces_.t2}) a->resize(n);
  for (auto* a : {&wall_forces_.x_wall, &wall_forces_.f, &wall_forces_.x_wall2, &wall_forces_.f2,
                  &wall_forces_.f_contact, &wall_forces_.f_contact2, &wall_forces_.f_viscous,
                  &wall_forces_.f_viscous2})
    a->resize(n);
  if (viscous) {
    // The wall hits of the last step's x* serve x^n (which differs by dt^2 |grad p| / rho, and
    // they see the walls at t^n) unless particles were reordered or removed since.
    if (hits_layout_ != layout_) query_walls();
    viscosity();
  }
  {
    Timer timer(times_.other);
    parallel_for(n, [&](std::size_t i) { // v* = v + dt (nu <lap v> + g), x* = x + dt v* (eq. 13)
      if (viscous) {
        p.vx[i] += dt * scratch_[2 * i];
        p.vy[i] += dt * scratch_[2 * i + 1];
      }
      p.vx[i] += dt * g.x();
      p.vy[i] += dt * g.y();
      p.x[i] += dt * p.vx[i];
      p.y[i] += dt * p.vy[i];
    });
  }
  check_finite(step_ + 1, t + dt); // v*, x* (before they are binned)
  refresh_neighbours(false, step_ + 1, t + dt);
  query_walls();
  const std::size_t crossed = first_index(n, [&](std::size_t i) { return hits_.crossed[i] != 0; });
  if (crossed != none)
    throw RunError("fluid: " + where(p, crossed, step_ + 1, t + dt) + " is behind wall segment " +
                   std::to_string(hits_.segment[crossed]) +
                   " (try a smaller time step or a larger alpha_rep)");
  density_and_pressure();
  pressure_gradient(dt);
  if (options_.wall_gap_courant > 0) {
    if (dt >= gap_dt_) ++gap_limited_steps_;
    gap_dt_ = wall_gap_dt();
  }
  ++step_;
  Timer timer(times_.other);
  damp(t, dt);
  check_finite(step_, t + dt);
  remove_outside();
}

void EmpsFluid::check_finite(long step, double t) const {
  const Particles& p = particles_;
  const std::size_t bad = first_index(p.size(), [&](std::size_t i) {
    return !std::isfinite(p.x[i] + p.y[i] + p.vx[i] + p.vy[i] + p.p[i]);
  });
  if (bad != none)
    throw RunError("fluid: non-finite position, velocity or pressure at " + where(p, bad, step, t));
}

void EmpsFluid::remove_outside() {
  Particles& p = particles_;
  const Vec2 lo = options_.domain_min, hi = options_.domain_max;
  keep_.resize(p.size());
  const std::size_t outside = parallel_reduce(
      p.size(), std::size_t{0},
      [&](std::size_t i) {
        const bool in =
            p.x[i] >= lo.x() && p.x[i] <= hi.x() && p.y[i] >= lo.y() && p.y[i] <= hi.y();
        keep_[i] = in;
        return std::size_t{in ? 0u : 1u};
      },
      [](std::size_t a, std::size_t b) { return a + b; });
  if (outside == 0) return;
  removed_ += p.compact(keep_);
  ++layout_;
  neighbours_.invalidate();
}

double EmpsFluid::kinetic_energy() const {
  const Particles& p = particles_;
  const double m = options_.density * options_.volume();
  return parallel_reduce(
      p.size(), 0.0,
      [&](std::size_t i) { return 0.5 * m * (p.vx[i] * p.vx[i] + p.vy[i] * p.vy[i]); },
      [](double a, double b) { return a + b; });
}

double EmpsFluid::max_speed() const {
  const Particles& p = particles_;
  return std::sqrt(parallel_reduce(
      p.size(), 0.0, [&](std::size_t i) { return p.vx[i] * p.vx[i] + p.vy[i] * p.vy[i]; },
      [](double a, double b) { return std::max(a, b); }));
}

void EmpsFluid::set_velocities(const std::vector<Vec2>& v) {
  if (v.size() != particles_.size())
    throw InputError("fluid: " + std::to_string(v.size()) + " initial velocities for " +
                     std::to_string(particles_.size()) + " particles");
  for (std::size_t i = 0; i < v.size(); ++i)
    particles_.vx[i] = v[i].x(), particles_.vy[i] = v[i].y();
}

double EmpsFluid::wall_gap_dt() const {
  // r at x^{n+1} to first order: the hit's r at x* plus the correction's move along n_wall
  // (scratch_ still holds it); the floor is repulsion()'s.
  const Particles& p = particles_;
  const double inf = std::numeric_limits<double>::infinity();
  const double min_gap = 0.5e-3 * options_.l0;
  auto face = [&](std::size_t i, int segment, double r, const Vec2& n, const Vec2& v_wall) {
    if (segment < 0) return inf;
    const double approach = -(Vec2(p.vx[i], p.vy[i]) - v_wall).dot(n);
    if (approach <= 0) return inf;
    const double gap = r + scratch_[2 * i] * n.x() + scratch_[2 * i + 1] * n.y();
    return options_.wall_gap_courant * std::max(gap, min_gap) / approach;
  };
  const erp::WallHits& h = hits_;
  return parallel_reduce(
      p.size(), inf,
      [&](std::size_t i) {
        return std::min(face(i, h.segment[i], h.r[i], h.n_wall[i], h.v_wall[i]),
                        face(i, h.segment2[i], h.r2[i], h.n_wall2[i], h.v_wall2[i]));
      },
      [](double a, double b) { return std::min(a, b); });
}

double EmpsFluid::stable_dt(double courant) const {
  double dt = courant * options_.l0 / (options_.sound_speed + max_speed());
  const double alpha =
      options_.artificial_viscosity + options_.wall_approach_viscosity +
      (options_.wall_contact == WallContact::viscous ? options_.wall_viscosity : 0.0);
  const double nu = options_.viscosity + alpha * options_.sound_speed * options_.l0;
  if (nu > 0) dt = std::min(dt, 0.25 * options_.l0 * options_.l0 / nu);
  if (options_.wall_gap_courant > 0) dt = std::min(dt, gap_dt_);
  return dt;
}

EmpsFluid::State EmpsFluid::save() const {
  State s{{}, step_, removed_, layout_, gap_dt_, gap_limited_steps_};
  particles_.fields.save(s.particles);
  return s;
}

void EmpsFluid::restore(const State& s) {
  particles_.fields.restore(s.particles);
  step_ = s.step;
  removed_ = s.removed;
  gap_dt_ = s.gap_dt;
  gap_limited_steps_ = s.gap_limited_steps;
  if (s.layout != layout_) {
    layout_ = s.layout;
    neighbours_.invalidate();
  }
  hits_layout_ = -1; // the hits belong to the abandoned step
}

namespace {
/// The Vec2 arrays of the wall hits, by checkpoint name.
template <class Hits> auto vector_hits(Hits& h) {
  return std::array{std::pair{"x_wall", &h.x_wall},   std::pair{"n_wall", &h.n_wall},
                    std::pair{"v_wall", &h.v_wall},   std::pair{"a_wall", &h.a_wall},
                    std::pair{"x_wall2", &h.x_wall2}, std::pair{"n_wall2", &h.n_wall2},
                    std::pair{"v_wall2", &h.v_wall2}};
}
} // namespace

void EmpsFluid::write_state(StateArchive& a, const std::string& prefix) const {
  particles_.fields.write_state(a, prefix);
  a.put_integer(prefix + "step", step_);
  a.put_integer(prefix + "removed", static_cast<std::int64_t>(removed_));
  a.put_integer(prefix + "layout", layout_);
  a.put_integer(prefix + "builds", builds_);
  a.put_real(prefix + "mean_neighbours", mean_neighbours_);
  if (options_.wall_gap_courant > 0) {
    a.put_real(prefix + "gap_dt", gap_dt_);
    a.put_integer(prefix + "gap_limited_steps", gap_limited_steps_);
  }
  // The list is rebuilt from its build positions on restart (same grid, same rows, same order).
  const std::size_t built = neighbours_.built();
  a.put(prefix + "neighbours/x_build",
        std::vector<double>(neighbours_.x_build().begin(),
                            neighbours_.x_build().begin() + static_cast<std::ptrdiff_t>(built)));
  a.put(prefix + "neighbours/y_build",
        std::vector<double>(neighbours_.y_build().begin(),
                            neighbours_.y_build().begin() + static_cast<std::ptrdiff_t>(built)));
  // Wall hits of the last x*, reused by the next viscous step while the layout is unchanged.
  const bool hits_valid = hits_layout_ == layout_;
  a.put_integer(prefix + "hits/valid", hits_valid);
  if (!hits_valid) return;
  const std::string h = prefix + "hits/";
  a.put_ints(h + "segment", hits_.segment);
  a.put_ints(h + "segment2", hits_.segment2);
  a.put_ints(h + "crossed", hits_.crossed);
  a.put(h + "t", hits_.t);
  a.put(h + "r", hits_.r);
  a.put(h + "t2", hits_.t2);
  a.put(h + "r2", hits_.r2);
  for (const auto& [name, v] : vector_hits(hits_)) a.put(h + name, flatten(*v));
}

void EmpsFluid::read_state(const StateArchive& a, const std::string& prefix) {
  particles_.fields.read_state(a, prefix);
  const std::size_t n = particles_.size();
  step_ = a.integer(prefix + "step");
  removed_ = static_cast<std::size_t>(a.integer(prefix + "removed"));
  layout_ = a.integer(prefix + "layout");
  builds_ = a.integer(prefix + "builds");
  mean_neighbours_ = a.real(prefix + "mean_neighbours");
  if (options_.wall_gap_courant > 0) {
    gap_dt_ = a.real(prefix + "gap_dt");
    gap_limited_steps_ = a.integer(prefix + "gap_limited_steps");
  }
  const auto& xb = a.reals(prefix + "neighbours/x_build");
  const auto& yb = a.reals(prefix + "neighbours/y_build", xb.size());
  neighbours_.invalidate();
  if (!xb.empty()) {
    if (xb.size() != n)
      throw InputError("checkpoint: '" + prefix +
                       "neighbours/x_build' does not match the particles");
    grid_.bin(xb.data(), yb.data(), n);
    if (!neighbours_.build(grid_, xb.data(), yb.data(), n, r_e_ * (1.0 + options_.skin), capacity_,
                           options_.vector_kernels))
      throw InputError("checkpoint: the stored neighbour list overflows");
  }
  hits_layout_ = -1;
  if (a.integer(prefix + "hits/valid") == 0) return;
  const std::string h = prefix + "hits/";
  const std::size_t m = a.integers(h + "segment").size();
  hits_.segment = a.ints<int>(h + "segment", m);
  hits_.segment2 = a.ints<int>(h + "segment2", m);
  hits_.crossed = a.ints<unsigned char>(h + "crossed", m);
  hits_.t = a.reals(h + "t", m);
  hits_.r = a.reals(h + "r", m);
  hits_.t2 = a.reals(h + "t2", m);
  hits_.r2 = a.reals(h + "r2", m);
  for (const auto& [name, v] : vector_hits(hits_)) *v = unflatten(a.reals(h + name, 2 * m));
  hits_layout_ = layout_;
}

} // namespace fsi::emps
