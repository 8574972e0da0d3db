#include "fluid_emps/emps_fluid.hpp"

#include "fluid_emps/wall_terms.hpp"
#include "fsi/core/error.hpp"
#include "fsi/core/option_ranges.hpp"
#include "fsi/core/parallel.hpp"
#include "particles/kernels.hpp"
#include "step_timer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace fsi::emps {

namespace {

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

void validate(FluidOptions o) {
  RangeChecker ranges("fluid.");
  visit_options(o, ranges); // the declared ranges of every key
  auto fail = [](const std::string& what) { throw InputError("fluid: " + what); };
  if (!(o.domain_max.x() > o.domain_min.x() && o.domain_max.y() > o.domain_min.y()))
    fail("the domain box is empty");
  if (!(o.skin > 0 && o.skin < 1)) fail("skin must be in (0, 1)");
}

} // namespace

EmpsFluid::EmpsFluid(const FluidOptions& options, const std::vector<Vec2>& positions,
                     erp::WallSet& walls)
    : options_((validate(options), options)),
      locator_(erp::make_wall_locator(walls, options.r_e())), r_e_(options.r_e()),
      n0_(erp::lattice_n0(options.l0, r_e_, particles::MpsWeight(r_e_))),
      lambda0_(erp::lattice_lambda0(options.l0, r_e_, particles::MpsWeight(r_e_))), w_e_(r_e_),
      re2_(r_e_ * r_e_), grid_(options.domain_min, options.domain_max, r_e_ * (1.0 + options.skin)),
      walls_(options, n0_, walls, particles_, grid_, hits_) {
  locator_->set_corner_faces(options.wall.corner_faces);
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
  const bool viscous = options_.viscous_loop();
  for (auto& v : visc_wall_) {
    if (viscous)
      v.resize(n);
    else
      v.assign(n, Vec2::Zero());
  }
  wall_forces_.resize(n);
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
                   std::to_string(hits_.face[0].segment[crossed]) +
                   " (try a smaller time step or a larger alpha_rep)");
  density_and_pressure();
  pressure_gradient(dt);
  if (options_.wall.gap_courant > 0) {
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

// The wall-gap limit of the next step (WallTerms::gap_dt), with the step's last position
// correction (scratch_ still holds it).
double EmpsFluid::wall_gap_dt() const {
  return parallel_reduce(
      particles_.size(), std::numeric_limits<double>::infinity(),
      [&](std::size_t i) { return walls_.gap_dt(i, scratch_[2 * i], scratch_[2 * i + 1]); },
      [](double a, double b) { return std::min(a, b); });
}

double EmpsFluid::stable_dt(double courant) const {
  double dt = courant * options_.l0 / (options_.sound_speed + max_speed());
  const double nu =
      options_.viscosity + options_.pair_viscosity_alpha() * options_.sound_speed * options_.l0;
  if (nu > 0) dt = std::min(dt, 0.25 * options_.l0 * options_.l0 / nu);
  if (options_.wall.gap_courant > 0) dt = std::min(dt, gap_dt_);
  return dt;
}

} // namespace fsi::emps
