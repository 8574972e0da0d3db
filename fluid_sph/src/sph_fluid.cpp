#include "fluid_sph/sph_fluid.hpp"

#include "wall_terms.hpp"

#include "fsi/core/error.hpp"
#include "fsi/core/format.hpp"
#include "fsi/core/parallel.hpp"
#include "fsi/core/state_archive.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace fsi::sph {

namespace {

constexpr std::size_t none = std::numeric_limits<std::size_t>::max();

/// Neighbour j at (dx, dy) = x_i - x_j into slot k of a pair set: e_ij, dW_ij, r_ij.
inline void store_pair(std::uint32_t k, std::uint32_t j, double dx, double dy,
                       const particles::WendlandC2& kernel, std::vector<std::uint32_t>& js,
                       std::vector<double>& ex, std::vector<double>& ey, std::vector<double>& dw,
                       std::vector<double>& rs) {
  const double r = std::sqrt(dx * dx + dy * dy);
  js[k] = j;
  ex[k] = dx / r;
  ey[k] = dy / r;
  dw[k] = kernel.dW(r);
  rs[k] = r;
}

std::string fmt(double v) {
  return significant(v, 6);
}

} // namespace

std::string to_string(Correction c) {
  return c == Correction::none ? "none" : "rkgc";
}

void SphOptions::validate() const {
  const auto fail = [](const std::string& key, double v, const std::string& range) {
    throw InputError("fluid_sph: " + key + " = " + fmt(v) + ", allowed " + range);
  };
  if (!(rho0 > 0.0)) fail("rho0", rho0, "> 0");
  if (!(c0 > 0.0)) fail("c0", c0, "> 0");
  if (!(dp > 0.0)) fail("dp", dp, "> 0");
  if (!(h_over_dp >= 1.0 && h_over_dp <= 2.0)) fail("h_over_dp", h_over_dp, "[1, 2]");
  if (!(viscosity >= 0.0)) fail("viscosity", viscosity, ">= 0");
  if (!(wkgc_alpha >= 0.0 && wkgc_alpha <= 1.0)) fail("wkgc_alpha", wkgc_alpha, "[0, 1]");
  if (!(transport_coefficient >= 0.0 && transport_coefficient <= 1.0))
    fail("transport_coefficient", transport_coefficient, "[0, 1]");
  if (transport_velocity && free_surface)
    throw InputError("fluid_sph: transport_velocity = true needs free_surface = false (eq. 24 is "
                     "for internal flows)");
  if (!(u_ref >= 0.0)) fail("u_ref", u_ref, ">= 0");
  if (!(advection_cfl > 0.0 && advection_cfl <= 1.0))
    fail("advection_cfl", advection_cfl, "(0, 1]");
  if (!(acoustic_cfl > 0.0 && acoustic_cfl <= 1.0)) fail("acoustic_cfl", acoustic_cfl, "(0, 1]");
  if (!(viscous_number >= 0.0 && viscous_number <= 0.5))
    fail("viscous_number", viscous_number, "[0, 0.5]");
  if (!(fixed_dt >= 0.0)) fail("fixed_dt", fixed_dt, ">= 0");
  if (!(damping_time >= 0.0)) fail("damping_time", damping_time, ">= 0");
  if (!(rho_min_factor > 0.0 && rho_min_factor < 1.0))
    fail("rho_min_factor", rho_min_factor, "(0, 1)");
  if (!(rho_max_factor > 1.0)) fail("rho_max_factor", rho_max_factor, "> 1");
  const Vec2 size = domain_max - domain_min;
  if (!(size.x() > 0.0)) fail("domain_max.x - domain_min.x", size.x(), "> 0");
  if (!(size.y() > 0.0)) fail("domain_max.y - domain_min.y", size.y(), "> 0");
  if (inflow.on()) {
    if (!periodic_x)
      throw InputError("fluid_sph: inflow.buffer > 0 needs periodic_x (the channel wraps in x)");
    if (!(inflow.buffer <= 0.5 * size.x()))
      fail("inflow.buffer", inflow.buffer, "(0, half the periodic length]");
    if (!(inflow.velocity > 0.0)) fail("inflow.velocity", inflow.velocity, "> 0");
    if (!(inflow.ramp_time >= 0.0)) fail("inflow.ramp_time", inflow.ramp_time, ">= 0");
    if (!(inflow.y_max > inflow.y_min))
      fail("inflow.y_max - inflow.y_min", inflow.y_max - inflow.y_min, "> 0");
  }
  const double cut = 2.0 * h();
  if (periodic_x && size.x() < 3.0 * cut)
    fail("periodic length x", size.x(), ">= 3 kernel supports (6 h)");
  if (periodic_y && size.y() < 3.0 * cut)
    fail("periodic length y", size.y(), ">= 3 kernel supports (6 h)");
}

std::vector<Vec2> fill_rectangle(const Vec2& lo, const Vec2& hi, double dp) {
  std::vector<Vec2> out;
  const int nx = static_cast<int>(std::floor((hi.x() - lo.x()) / dp + 1e-9));
  const int ny = static_cast<int>(std::floor((hi.y() - lo.y()) / dp + 1e-9));
  out.reserve(static_cast<std::size_t>(std::max(nx, 0) * std::max(ny, 0)));
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) out.emplace_back(lo.x() + (i + 0.5) * dp, lo.y() + (j + 0.5) * dp);
  return out;
}

SphFluid::SphFluid(const SphOptions& options, const std::vector<Vec2>& positions,
                   const std::vector<WallPolyline>& walls, const std::vector<WallPoint>& points,
                   std::vector<WallDistance> distances)
    : options_(options), kernel_((options.validate(), options.h())), h_(options.h()), sigma0_(0.0),
      mass_(options.mass()), distances_(std::move(distances)) {
  const double dp = options_.dp;
  // sigma0: the lattice sum of W (method notes, "Kernel and resolution").
  const int reach = static_cast<int>(std::ceil(kernel_.cutoff() / dp)) + 1;
  for (int j = -reach; j <= reach; ++j)
    for (int i = -reach; i <= reach; ++i) sigma0_ += kernel_.W(dp * std::hypot(i, j));

  const Vec2& lo = options_.domain_min;
  const Vec2& hi = options_.domain_max;
  grid_ =
      particles::PeriodicGrid(lo, hi, kernel_.cutoff(), options_.periodic_x, options_.periodic_y);
  wall_grid_ = grid_;

  const std::size_t n = positions.size();
  fluid_.fields.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& r = positions[i];
    if (!(r.x() >= lo.x() && r.x() <= hi.x() && r.y() >= lo.y() && r.y() <= hi.y()))
      throw InputError("fluid_sph: particle " + std::to_string(i) + " at (" + fmt(r.x()) + ", " +
                       fmt(r.y()) + ") is outside the domain");
    fluid_.id[i] = static_cast<std::uint32_t>(i);
    fluid_.x[i] = r.x();
    fluid_.y[i] = r.y();
    fluid_.rho[i] = options_.rho0;
    fluid_.vol[i] = dp * dp;
    fluid_.b00[i] = fluid_.b11[i] = 1.0;
    fluid_.apx[i] = fluid_.ax[i] = options_.gravity.x();
    fluid_.apy[i] = fluid_.ay[i] = options_.gravity.y();
  }
  fill_walls(walls);
  append_wall_points(points);
  // The first advection step starts here: its per-Dt work runs as at the end of any other.
  builds_ = -1;
  per_advection_step();
}

void SphFluid::fill_walls(const std::vector<WallPolyline>& walls) {
  // Dummy particles: lattice points at (i + 1/2) dp from each polyline's first point that lie on
  // the wall side (right of the nearest segment; at a vertex, of the sum of the two normals) within
  // 4 dp of the polyline. Their normal is that of the nearest feature, into the fluid, and their
  // depth the distance behind that feature's line along it ((k + 1/2) dp for layer k of a wall).
  const double dp = options_.dp, depth = 4.0 * dp;
  std::vector<Vec2> xs, ns;
  std::vector<double> ds;
  std::vector<std::uint32_t> groups;
  for (const WallPolyline& w : walls) {
    const std::size_t m = w.points.size();
    if (m < 2) throw InputError("fluid_sph: a wall polyline needs >= 2 points");
    if (w.group < 0) throw InputError("fluid_sph: wall group " + std::to_string(w.group) + " < 0");
    const std::size_t segs = w.closed ? m : m - 1;
    Vec2 bmin = w.points[0], bmax = w.points[0];
    for (const Vec2& q : w.points) bmin = bmin.cwiseMin(q), bmax = bmax.cwiseMax(q);
    const Vec2 origin = w.points[0];
    const int i0 = static_cast<int>(std::floor((bmin.x() - depth - origin.x()) / dp)) - 1;
    const int i1 = static_cast<int>(std::ceil((bmax.x() + depth - origin.x()) / dp)) + 1;
    const int j0 = static_cast<int>(std::floor((bmin.y() - depth - origin.y()) / dp)) - 1;
    const int j1 = static_cast<int>(std::ceil((bmax.y() + depth - origin.y()) / dp)) + 1;
    const auto normal = [&](std::size_t s) { // left normal of segment s
      const Vec2 d = (w.points[(s + 1) % m] - w.points[s]).normalized();
      return Vec2(-d.y(), d.x());
    };
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) {
        const Vec2 q = origin + Vec2((i + 0.5) * dp, (j + 0.5) * dp);
        double best = std::numeric_limits<double>::max();
        Vec2 n_best = Vec2::Zero();
        bool open_end = false;
        double side = 0.0;
        for (std::size_t s = 0; s < segs; ++s) {
          const Vec2 a = w.points[s], b = w.points[(s + 1) % m];
          const Vec2 ab = b - a;
          const double t = std::clamp((q - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
          const double dist = (q - (a + t * ab)).norm();
          if (dist >= best - 1e-12 * dp) continue;
          best = dist;
          Vec2 n = normal(s);
          open_end = false;
          if (t <= 0.0 || t >= 1.0) { // nearest feature is a vertex
            const bool at_a = t <= 0.0;
            const std::size_t v = at_a ? s : (s + 1) % m;
            const bool has_other = w.closed || (at_a ? s > 0 : s + 1 < segs);
            if (has_other) {
              const std::size_t other = at_a ? (s + segs - 1) % segs : (s + 1) % segs;
              n = (n + normal(other)).normalized();
            } else {
              open_end = true;
            }
            side = (q - w.points[v]).dot(n);
          } else {
            side = (q - a).dot(n);
          }
          n_best = n;
        }
        if (open_end || best >= depth || side >= 0.0) continue;
        xs.push_back(q);
        ns.push_back(n_best);
        ds.push_back(-side);
        groups.push_back(static_cast<std::uint32_t>(w.group));
      }
  }
  const std::size_t nw = xs.size();
  walls_.fields.resize(nw);
  for (std::size_t a = 0; a < nw; ++a) {
    walls_.group[a] = groups[a];
    walls_.x[a] = walls_.x0[a] = walls_.xb[a] = xs[a].x();
    walls_.y[a] = walls_.y0[a] = walls_.yb[a] = xs[a].y();
    walls_.nx[a] = walls_.nx0[a] = ns[a].x();
    walls_.ny[a] = walls_.ny0[a] = ns[a].y();
    walls_.depth[a] = ds[a];
    walls_.vol[a] = dp * dp;
  }
}

void SphFluid::set_velocities(const std::vector<Vec2>& v) {
  if (v.size() != fluid_.size() || removed_ > 0)
    throw InputError("fluid_sph: " + std::to_string(v.size()) + " initial velocities for " +
                     std::to_string(fluid_.size()) + " particles");
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Vec2& w = v[fluid_.id[i]];
    fluid_.vx[i] = w.x(), fluid_.vy[i] = w.y();
  }
  // The viscous force and Dt depend on the velocities: redo this advection step's start.
  prior_acceleration();
  compute_advection_dt();
  if (options_.fixed_dt > 0.0) {
    subs_ = std::max(1L, static_cast<long>(std::floor(Dt_ / options_.fixed_dt)));
    Dt_ = static_cast<double>(subs_) * options_.fixed_dt;
  }
  compute_acoustic_dt();
}

void SphFluid::set_wall_motion(int group, WallMotion motion) {
  if (group < 0) throw InputError("fluid_sph: wall group " + std::to_string(group) + " < 0");
  if (motions_.size() <= static_cast<std::size_t>(group))
    motions_.resize(static_cast<std::size_t>(group) + 1);
  motions_[static_cast<std::size_t>(group)] = std::move(motion);
}

double SphFluid::next_dt() const {
  if (options_.fixed_dt > 0.0) return options_.fixed_dt;
  return std::min(dt_acoustic_, Dt_ - elapsed_);
}

void SphFluid::advance(double dt) {
  const double left = Dt_ - elapsed_;
  if (!(dt > 0.0) || (options_.fixed_dt <= 0.0 && dt > left * (1.0 + 1e-12)))
    throw InputError("fluid_sph: acoustic step " + fmt(dt) + " not in (0, " + fmt(left) +
                     "] (what is left of the advection step)");
  move_walls(dt);
  first_half(dt);
  if (tracked_ < walls_.size()) wall_reaction();
  second_half(dt);
  if (options_.inflow.on()) impose_inflow(t_ + dt);
  if (options_.damping_time > 0.0 && t_ < options_.damping_time) {
    const double T = options_.damping_time;
    const double keep = std::max(0.0, 1.0 - dt * 20.0 / T * (1.0 - t_ / T));
    parallel_for(fluid_.size(), [&](std::size_t i) {
      fluid_.vx[i] *= keep;
      fluid_.vy[i] *= keep;
    });
  }
  t_ += dt;
  ++step_;
  elapsed_ += dt;
  guard(step_, t_);
  const bool filled = options_.fixed_dt > 0.0 ? ++sub_ >= subs_ : dt >= left * (1.0 - 1e-12);
  if (filled) per_advection_step();
}

void SphFluid::advance_to(double t_end) {
  while (t_ < t_end - 1e-12 * std::max(1.0, std::abs(t_end))) {
    double dt = next_dt();
    if (options_.fixed_dt <= 0.0) dt = std::min(dt, t_end - t_);
    advance(dt);
  }
}

void SphFluid::move_walls(double dt) {
  if (motions_.empty()) return;
  for (std::size_t g = 0; g < motions_.size(); ++g) {
    if (!motions_[g]) continue;
    const RigidMotion m0 = motions_[g](t_), m1 = motions_[g](t_ + dt);
    const double c0 = std::cos(m0.theta), s0 = std::sin(m0.theta);
    const double c1 = std::cos(m1.theta), s1 = std::sin(m1.theta);
    const double inv_dt = 1.0 / dt;
    parallel_for(walls_.size(), [&](std::size_t a) {
      if (walls_.group[a] != g) return;
      const Vec2 X(walls_.x0[a] - m0.centre.x(), walls_.y0[a] - m0.centre.y());
      const Vec2 r0(c0 * X.x() - s0 * X.y(), s0 * X.x() + c0 * X.y());
      const Vec2 r1(c1 * X.x() - s1 * X.y(), s1 * X.x() + c1 * X.y());
      const Vec2 x0 = m0.centre + m0.d + r0, x1 = m1.centre + m1.d + r1;
      const Vec2 v0 = m0.v + m0.omega * Vec2(-r0.y(), r0.x());
      const Vec2 v1 = m1.v + m1.omega * Vec2(-r1.y(), r1.x());
      // Velocity and acceleration averaged over the acoustic step (eq. 17, ref. [54]).
      walls_.vx[a] = (x1.x() - x0.x()) * inv_dt;
      walls_.vy[a] = (x1.y() - x0.y()) * inv_dt;
      walls_.ax[a] = (v1.x() - v0.x()) * inv_dt;
      walls_.ay[a] = (v1.y() - v0.y()) * inv_dt;
      walls_.x[a] = x1.x();
      walls_.y[a] = x1.y();
      walls_.nx[a] = c1 * walls_.nx0[a] - s1 * walls_.ny0[a];
      walls_.ny[a] = s1 * walls_.nx0[a] + c1 * walls_.ny0[a];
    });
  }
}

void SphFluid::first_half(double dt) {
  auto& f = fluid_;
  const double half = 0.5 * dt, c2 = options_.c0 * options_.c0, rho0 = options_.rho0;
  parallel_for(f.size(), [&](std::size_t i) {
    f.rho[i] += f.drho[i] * half;
    f.p[i] = c2 * (f.rho[i] - rho0); // eq. 2
    f.x[i] += f.vx[i] * half;
    f.y[i] += f.vy[i] * half;
  });
  const double rho0c0 = rho0 * options_.c0, inv_c0 = 1.0 / options_.c0, inv_m = 1.0 / mass_;
  const bool lim = options_.riemann_limiter;
  const double rho0c0_pairs = options_.pair_dissipation ? rho0c0 : 0.0;
  parallel_for(f.size(), [&](std::size_t i) {
    const double p_i = f.p[i], vx_i = f.vx[i], vy_i = f.vy[i];
    const double b00 = f.b00[i], b01 = f.b01[i], b11 = f.b11[i];
    double fx = 0.0, fy = 0.0;
    for (std::uint32_t k = pstart_[i]; k < pstart_[i + 1]; ++k) {
      const std::uint32_t j = pj_[k];
      const double ex = pex_[k], ey = pey_[k], dWV = pdw_[k] * f.vol[j];
      const double p_j = f.p[j];
      // (p_i B_j + p_j B_i) grad W_ij V_j (eqs. 18, 20).
      const double gx = dWV * ex, gy = dWV * ey;
      fx -= p_i * (f.b00[j] * gx + f.b01[j] * gy) + p_j * (b00 * gx + b01 * gy);
      fy -= p_i * (f.b01[j] * gx + f.b11[j] * gy) + p_j * (b01 * gx + b11 * gy);
      // Riemann dissipation: -2 (P* - p_bar) grad W = beta rho0 c0 u grad W (eq. 5).
      const double u = (vx_i - f.vx[j]) * ex + (vy_i - f.vy[j]) * ey;
      const double d = rho0c0_pairs * limiter(u, inv_c0, lim) * u;
      fx += d * gx;
      fy += d * gy;
    }
    // Walls (eqs. 15-17): dummy pressure p_d = p_i + rho_i r max(0, (a_prior - a_w) . (-e_ia)).
    const double apx = f.apx[i], apy = f.apy[i], rho_i = f.rho[i];
    for (std::uint32_t k = wstart_[i]; k < wstart_[i + 1]; ++k) {
      const std::uint32_t a = wj_[k];
      const Vec2 t =
          wall_term({p_i, rho_i, wr_[k], apx - walls_.ax[a], apy - walls_.ay[a], wex_[k], wey_[k],
                     wdw_[k] * walls_.vol[a], b00, b01, b11, vx_i - walls_.vx[a],
                     vy_i - walls_.vy[a], walls_.nx[a], walls_.ny[a], rho0c0, inv_c0, lim});
      fx += t.x();
      fy += t.y();
    }
    const double s = f.vol[i] * inv_m;
    f.ax[i] = fx * s + apx;
    f.ay[i] = fy * s + apy;
  });
}

void SphFluid::second_half(double dt) {
  auto& f = fluid_;
  const double half = 0.5 * dt;
  parallel_for(f.size(), [&](std::size_t i) {
    f.vx[i] += f.ax[i] * dt;
    f.vy[i] += f.ay[i] * dt;
    f.x[i] += f.vx[i] * half;
    f.y[i] += f.vy[i] * half;
  });
  const double inv_rho0c0 = 1.0 / (options_.rho0 * options_.c0);
  const double c0 = options_.c0, four_h = 4.0 * h_;
  const double worst = parallel_reduce(
      f.size(), 0.0,
      [&](std::size_t i) {
        const double p_i = f.p[i], vx_i = f.vx[i], vy_i = f.vy[i];
        double s = 0.0;
        // Continuity (eqs. 3, 5): rho_i sum [(v_i - v_j) . e_ij + (p_i - p_j) / (rho0 c0)] dW V_j.
        for (std::uint32_t k = pstart_[i]; k < pstart_[i + 1]; ++k) {
          const std::uint32_t j = pj_[k];
          const double u = (vx_i - f.vx[j]) * pex_[k] + (vy_i - f.vy[j]) * pey_[k];
          s += (u + (p_i - f.p[j]) * inv_rho0c0) * pdw_[k] * f.vol[j];
        }
        // Walls: v_d = 2 v_w - v_i, so v_i - v_d = 2 (v_i - v_w); the pressure term with the
        // dummy pressure p_d of eq. 16 (the reference code's wall density diffusion).
        const double apx = f.apx[i], apy = f.apy[i], rho_i = f.rho[i];
        for (std::uint32_t k = wstart_[i]; k < wstart_[i + 1]; ++k) {
          const std::uint32_t a = wj_[k];
          const double ex = wex_[k], ey = wey_[k];
          const double u = (vx_i - walls_.vx[a]) * ex + (vy_i - walls_.vy[a]) * ey;
          const double p_id =
              -dummy_jump(rho_i, wr_[k], apx - walls_.ax[a], apy - walls_.ay[a], ex, ey);
          s += (2.0 * u + p_id * inv_rho0c0) * wdw_[k] * walls_.vol[a];
        }
        f.drho[i] = f.rho[i] * s;
        f.rho[i] += f.drho[i] * half;
        // Acoustic criterion: max(c0 + |v|, sqrt(4 h |a|)).
        const double v = std::sqrt(vx_i * vx_i + vy_i * vy_i);
        const double a = std::sqrt(f.ax[i] * f.ax[i] + f.ay[i] * f.ay[i]);
        return std::max(c0 + v, std::sqrt(four_h * a));
      },
      [](double a, double b) { return std::max(a, b); }); // NaN-safe: a NaN is caught by guard()
  dt_acoustic_ = options_.acoustic_cfl * h_ / worst;
}

std::string SphFluid::where(std::size_t i, long step, double t) const {
  return "particle " + std::to_string(fluid_.id[i]) + " at (" + fmt(fluid_.x[i]) + ", " +
         fmt(fluid_.y[i]) + "), step " + std::to_string(step) + ", t = " + fmt(t) + " s";
}

void SphFluid::guard(long step, double t) const {
  const auto& f = fluid_;
  const double lo = options_.rho_min_factor * options_.rho0,
               hi = options_.rho_max_factor * options_.rho0;
  const std::size_t bad = parallel_reduce(
      f.size(), none,
      [&](std::size_t i) {
        const bool ok = std::isfinite(f.x[i]) && std::isfinite(f.y[i]) && std::isfinite(f.vx[i]) &&
                        std::isfinite(f.vy[i]) && f.rho[i] >= lo && f.rho[i] <= hi;
        return ok ? none : i;
      },
      [](std::size_t a, std::size_t b) { return std::min(a, b); });
  if (bad == none) return;
  const double r = f.rho[bad];
  if (std::isfinite(r) && std::isfinite(f.vx[bad]) && std::isfinite(f.vy[bad]))
    throw RunError("fluid_sph: density " + fmt(r) + " out of [" + fmt(lo) + ", " + fmt(hi) +
                   "] at " + where(bad, step, t));
  throw RunError("fluid_sph: non-finite position, velocity or density at " + where(bad, step, t));
}

void SphFluid::per_advection_step() {
  auto& f = fluid_;
  compute_advection_dt();
  // Periodic wrap; particles that left a non-periodic side of the domain are removed.
  const Vec2 lo = options_.domain_min, hi = options_.domain_max;
  keep_.assign(f.size(), 1);
  bool any_out = false;
  for (std::size_t i = 0; i < f.size(); ++i) {
    f.x[i] = grid_.wrap_x(f.x[i]);
    f.y[i] = grid_.wrap_y(f.y[i]);
    if ((!options_.periodic_x && (f.x[i] < lo.x() || f.x[i] > hi.x())) ||
        (!options_.periodic_y && (f.y[i] < lo.y() || f.y[i] > hi.y())))
      keep_[i] = 0, any_out = true;
  }
  if (any_out) removed_ += f.fields.compact(keep_);
  // Sort by cell (particles of a cell contiguous, neighbours close in memory).
  grid_.bin(f.x.data(), f.y.data(), f.size());
  f.fields.permute(grid_.order(), scratch_);
  std::copy(f.x.begin(), f.x.end(), f.xb.begin());
  std::copy(f.y.begin(), f.y.end(), f.yb.begin());
  std::copy(walls_.x.begin(), walls_.x.end(), walls_.xb.begin());
  std::copy(walls_.y.begin(), walls_.y.end(), walls_.yb.begin());
  build_pairs();
  ++builds_;
  reinitialise_density();
  correction_matrices();
  prior_acceleration();
  if (options_.transport_velocity) transport_shift();
  elapsed_ = 0.0;
  sub_ = 0;
  if (options_.fixed_dt > 0.0) {
    subs_ = std::max(1L, static_cast<long>(std::floor(Dt_ / options_.fixed_dt)));
    Dt_ = static_cast<double>(subs_) * options_.fixed_dt;
  }
  if (dt_acoustic_ <= 0.0) compute_acoustic_dt();
}

void SphFluid::compute_acoustic_dt() {
  const auto& f = fluid_;
  double worst = options_.c0;
  for (std::size_t i = 0; i < f.size(); ++i) {
    const double v = std::hypot(f.vx[i], f.vy[i]), a = std::hypot(f.ax[i], f.ay[i]);
    worst = std::max(worst, std::max(options_.c0 + v, std::sqrt(4.0 * h_ * a)));
  }
  dt_acoustic_ = options_.acoustic_cfl * h_ / worst;
}

void SphFluid::compute_advection_dt() {
  const auto& f = fluid_;
  const double four_h = 4.0 * h_;
  // Dt = 0.25 h / max(sqrt(max(|v|^2, 4 h |a|)), U_ref, nu / h) (method notes).
  const double worst = parallel_reduce(
      f.size(), 0.0,
      [&](std::size_t i) {
        const double v2 = f.vx[i] * f.vx[i] + f.vy[i] * f.vy[i];
        const double a = std::sqrt(f.ax[i] * f.ax[i] + f.ay[i] * f.ay[i]);
        return std::max(v2, four_h * a);
      },
      [](double a, double b) { return std::max(a, b); });
  const double speed =
      std::max({std::sqrt(worst), options_.u_advection(), options_.viscosity / h_});
  Dt_ = options_.advection_cfl * h_ / speed;
  // The viscous term is frozen over Dt (explicit): its diffusion number nu Dt / h^2 stays below
  // viscous_number (the Taylor-Green decay gains 5 % at 0.19, docs/fluid_sph.md).
  const double nu = options_.viscosity, number = options_.viscous_number;
  if (nu > 0.0 && number > 0.0) Dt_ = std::min(Dt_, number * h_ * h_ / nu);
}

void SphFluid::build_pairs(bool guard) {
  auto& f = fluid_;
  const std::size_t n = f.size(), nw = walls_.size();
  grid_.bin(f.xb.data(), f.yb.data(), n);
  wall_grid_.bin(walls_.xb.data(), walls_.yb.data(), nw);
  const double cut2 = kernel_.cutoff() * kernel_.cutoff();
  count_.resize(2 * n);
  parallel_for_balanced(n, [&](std::size_t i) {
    const double xi = f.xb[i], yi = f.yb[i];
    std::uint32_t c = 0, cw = 0;
    grid_.for_each_near(xi, yi, [&](std::uint32_t j, double sx, double sy) {
      const double dx = xi - f.xb[j] - sx, dy = yi - f.yb[j] - sy;
      const double r2 = dx * dx + dy * dy;
      if (j != i && r2 < cut2 && r2 > 0.0) ++c;
    });
    wall_grid_.for_each_near(xi, yi, [&](std::uint32_t a, double sx, double sy) {
      const double dx = xi - walls_.xb[a] - sx, dy = yi - walls_.yb[a] - sy;
      const double r2 = dx * dx + dy * dy;
      if (r2 < cut2 && r2 > 0.0) ++cw;
    });
    count_[i] = c;
    count_[n + i] = cw;
  });
  pstart_.resize(n + 1);
  wstart_.resize(n + 1);
  pstart_[0] = wstart_[0] = 0;
  for (std::size_t i = 0; i < n; ++i) {
    pstart_[i + 1] = pstart_[i] + count_[i];
    wstart_[i + 1] = wstart_[i] + count_[n + i];
  }
  // Grow only (with headroom): no allocation in the usual advection step.
  if (pstart_[n] > pj_.size()) {
    const std::size_t m = pstart_[n] + pstart_[n] / 8 + 16;
    pj_.resize(m), pex_.resize(m), pey_.resize(m), pdw_.resize(m), pr_.resize(m);
  }
  if (wstart_[n] > wj_.size()) {
    const std::size_t m = wstart_[n] + wstart_[n] / 8 + 16;
    wj_.resize(m), wex_.resize(m), wey_.resize(m), wdw_.resize(m), wr_.resize(m);
  }
  // Fill, in the same visiting order, then the through-a-wall guard (issue 20, Antoci's gate):
  // from wall point a, with p = (x_i - x_a) . n_a - depth_a and q = (x_i - x_a) x n_a, the
  // particle's signed distance to the wall surface is s_a = p on a face, the same from every
  // point of a flat face (all layers); on the bisector of a convex corner whose faces' normals
  // are 2 phi apart, with corner_a = sin(phi), s_a = cos(phi) p + sin(phi) |q|, the larger of
  // the signed distances to the two faces' lines through the corner. A particle is behind the
  // walls when s_a < -dp/2 (the first layer's plane, the guard's tolerance) for the nearest
  // point AND every point within 1.5 dp more (the nearest's lattice neighbours, dp and
  // sqrt(2) dp away): the intersection of half-planes, the inside test at a convex corner,
  // where a particle beside a thin body's end is behind the end face's plane but in front of
  // the side face. Given up: a particle through a face near a concave corner is caught only
  // once it is out of the other face's range (about a dp from it); acceptable for a guard,
  // which only has to stop a run whose particles get well through a wall. At a flat wall it
  // flags what the nearest point's plane did, and a particle past the first layer too. Where the
  // caller gave the nearest point's group an exact surface (the constructor's distances), a
  // particle is flagged only if that surface puts it behind the tolerance too: the end face of a
  // body 2 dp thick may have no point of its own (its row nearer the side faces), and a particle
  // above that end is then behind both sides' planes.
  const double reach = 1.5 * options_.dp, tolerance = -0.5 * options_.dp;
  const std::size_t behind = parallel_reduce_balanced(
      n, none,
      [&](std::size_t i) {
        const double xi = f.xb[i], yi = f.yb[i];
        std::uint32_t k = pstart_[i];
        grid_.for_each_near(xi, yi, [&](std::uint32_t j, double sx, double sy) {
          const double dx = xi - f.xb[j] - sx, dy = yi - f.yb[j] - sy;
          const double r2 = dx * dx + dy * dy;
          if (j == i || r2 >= cut2 || r2 <= 0.0) return;
          store_pair(k++, j, dx, dy, kernel_, pj_, pex_, pey_, pdw_, pr_);
        });
        const std::uint32_t kw0 = wstart_[i];
        std::uint32_t kw = kw0;
        double nearest = cut2;
        std::uint32_t a_nearest = 0;
        wall_grid_.for_each_near(xi, yi, [&](std::uint32_t a, double sx, double sy) {
          const double dx = xi - walls_.xb[a] - sx, dy = yi - walls_.yb[a] - sy;
          const double r2 = dx * dx + dy * dy;
          if (r2 >= cut2 || r2 <= 0.0) return;
          store_pair(kw++, a, dx, dy, kernel_, wj_, wex_, wey_, wdw_, wr_);
          if (r2 < nearest) nearest = r2, a_nearest = a;
        });
        if (!guard) return none;
        const double within = std::sqrt(nearest) + reach;
        for (std::uint32_t k = kw0; k < kw; ++k) {
          if (wr_[k] > within) continue;
          const std::uint32_t a = wj_[k];
          const double nx = walls_.nx[a], ny = walls_.ny[a], sine = walls_.corner[a];
          const double p = wr_[k] * (wex_[k] * nx + wey_[k] * ny) - walls_.depth[a];
          const double q = wr_[k] * (wex_[k] * ny - wey_[k] * nx);
          if (std::sqrt(1.0 - sine * sine) * p + sine * std::abs(q) >= tolerance) return none;
        }
        if (kw == kw0) return none;
        // The group's exact surface, where the caller gave it (at the positions of the pairs).
        const std::size_t g = walls_.group[a_nearest];
        if (g < distances_.size() && distances_[g] && distances_[g](Vec2(xi, yi)) >= tolerance)
          return none;
        return i;
      },
      [](std::size_t a, std::size_t b) { return std::min(a, b); });
  if (behind != none)
    throw RunError("fluid_sph: behind the first wall layer (through a wall): " +
                   where(behind, step_, t_));
}

double SphFluid::kernel_sum(std::size_t i) const {
  double sigma = kernel_.W(0.0);
  for (std::uint32_t k = pstart_[i]; k < pstart_[i + 1]; ++k) sigma += kernel_.W(pr_[k]);
  // A wall particle counts as V_a / dp^2 lattice particles (a dummy as exactly one).
  const double dp2 = options_.dp * options_.dp;
  for (std::uint32_t k = wstart_[i]; k < wstart_[i + 1]; ++k)
    sigma += kernel_.W(wr_[k]) * (walls_.vol[wj_[k]] / dp2);
  return sigma;
}

void SphFluid::reinitialise_density() {
  auto& f = fluid_;
  const double rho0 = options_.rho0, inv_sigma0 = 1.0 / sigma0_;
  const bool free_surface = options_.free_surface;
  const double dp2 = options_.dp * options_.dp;
  parallel_for(f.size(), [&](std::size_t i) {
    const double rho_sum = rho0 * kernel_sum(i) * inv_sigma0;
    if (free_surface) {
      f.rho[i] = std::max(rho_sum, rho0);
      f.vol[i] = dp2;
    } else {
      f.rho[i] = rho_sum;
      f.vol[i] = mass_ / rho_sum;
    }
  });
}

void SphFluid::correction_matrices() {
  auto& f = fluid_;
  const bool on = options_.correction == Correction::rkgc;
  const double alpha = options_.wkgc_alpha;
  parallel_for(f.size(), [&](std::size_t i) {
    // A_i = -sum_j r_ij (x) grad W_ij V_j = -sum_j r dW e (x) e V_j (eq. 19), symmetric.
    double a00 = 0.0, a01 = 0.0, a11 = 0.0;
    for (std::uint32_t k = pstart_[i]; k < pstart_[i + 1]; ++k) {
      const double s = -pr_[k] * pdw_[k] * f.vol[pj_[k]];
      a00 += s * pex_[k] * pex_[k];
      a01 += s * pex_[k] * pey_[k];
      a11 += s * pey_[k] * pey_[k];
    }
    for (std::uint32_t k = wstart_[i]; k < wstart_[i + 1]; ++k) {
      const double s = -wr_[k] * wdw_[k] * walls_.vol[wj_[k]];
      a00 += s * wex_[k] * wex_[k];
      a01 += s * wex_[k] * wey_[k];
      a11 += s * wey_[k] * wey_[k];
    }
    const double det = a00 * a11 - a01 * a01;
    f.det_a[i] = det;
    if (!on) {
      f.b00[i] = f.b11[i] = 1.0;
      f.b01[i] = 0.0;
      return;
    }
    // B = (A^T A + eps I)^-1 A^T (regularised inverse; A symmetric).
    const double eps = 1e-12;
    const double m00 = a00 * a00 + a01 * a01 + eps, m01 = a00 * a01 + a01 * a11;
    const double m11 = a01 * a01 + a11 * a11 + eps;
    const double inv = 1.0 / (m00 * m11 - m01 * m01);
    const double i00 = m11 * inv, i01 = -m01 * inv, i11 = m00 * inv;
    double b00 = i00 * a00 + i01 * a01, b01 = i00 * a01 + i01 * a11, b11 = i01 * a01 + i11 * a11;
    // WKGC (eqs. 21-22): B~ = w1 B + w2 I, kappa = max(alpha - |A|, 0).
    const double d = std::max(det, 0.0), kappa = std::max(alpha - d, 0.0);
    if (d + kappa <= 0.0) {
      b00 = b11 = 1.0, b01 = 0.0;
    } else {
      const double w1 = d / (d + kappa), w2 = kappa / (d + kappa);
      b00 = w1 * b00 + w2;
      b01 = w1 * b01;
      b11 = w1 * b11 + w2;
    }
    f.b00[i] = b00;
    f.b01[i] = b01;
    f.b11[i] = b11;
  });
}

void SphFluid::prior_acceleration() {
  auto& f = fluid_;
  const Vec2 g = options_.gravity;
  const double mu = options_.rho0 * options_.viscosity, reg = 0.01 * h_;
  const double inv_m = 1.0 / mass_;
  parallel_for(f.size(), [&](std::size_t i) {
    double fx = 0.0, fy = 0.0;
    if (mu > 0.0) {
      // Viscous force 2 mu V_i sum_j V_j (v_i - v_j) dW / (r + 0.01 h) (eq. 3); no-slip walls
      // with the dummy velocity 2 v_w - v_i (eqs. 15, 17).
      const double vx_i = f.vx[i], vy_i = f.vy[i];
      for (std::uint32_t k = pstart_[i]; k < pstart_[i + 1]; ++k) {
        const std::uint32_t j = pj_[k];
        const double s = pdw_[k] * f.vol[j] / (pr_[k] + reg);
        fx += (vx_i - f.vx[j]) * s;
        fy += (vy_i - f.vy[j]) * s;
      }
      for (std::uint32_t k = wstart_[i]; k < wstart_[i + 1]; ++k) {
        const std::uint32_t a = wj_[k];
        const double s = wall_viscous_weight(wdw_[k], walls_.vol[a], wr_[k], reg);
        fx += (vx_i - walls_.vx[a]) * s;
        fy += (vy_i - walls_.vy[a]) * s;
      }
      const double c = 2.0 * mu * f.vol[i] * inv_m;
      fx *= c;
      fy *= c;
    }
    f.apx[i] = g.x() + fx;
    f.apy[i] = g.y() + fy;
  });
  if (tracked_ < walls_.size()) wall_viscous_reaction();
}

void SphFluid::transport_shift() {
  auto& f = fluid_;
  const double c = options_.transport_coefficient * h_ * h_;
  auto& dx = scratch_;
  dx.resize(2 * f.size());
  parallel_for(f.size(), [&](std::size_t i) {
    // Delta r_i = 0.2 h^2 (-sum_j (B_i + B_j) grad W_ij V_j - sum_a 2 B_i grad W_ia V_a)
    // (eq. 24 in the reference code's sign, method notes).
    double sx = 0.0, sy = 0.0;
    const double b00 = f.b00[i], b01 = f.b01[i], b11 = f.b11[i];
    for (std::uint32_t k = pstart_[i]; k < pstart_[i + 1]; ++k) {
      const std::uint32_t j = pj_[k];
      const double gx = pdw_[k] * f.vol[j] * pex_[k], gy = pdw_[k] * f.vol[j] * pey_[k];
      sx += (b00 + f.b00[j]) * gx + (b01 + f.b01[j]) * gy;
      sy += (b01 + f.b01[j]) * gx + (b11 + f.b11[j]) * gy;
    }
    for (std::uint32_t k = wstart_[i]; k < wstart_[i + 1]; ++k) {
      const double vw = walls_.vol[wj_[k]];
      const double gx = wdw_[k] * vw * wex_[k], gy = wdw_[k] * vw * wey_[k];
      sx += 2.0 * (b00 * gx + b01 * gy);
      sy += 2.0 * (b01 * gx + b11 * gy);
    }
    dx[2 * i] = -c * sx;
    dx[2 * i + 1] = -c * sy;
  });
  parallel_for(f.size(), [&](std::size_t i) {
    f.x[i] += dx[2 * i];
    f.y[i] += dx[2 * i + 1];
  });
}

double SphFluid::mean_neighbours() const {
  const std::size_t n = fluid_.size();
  if (n == 0) return 0.0;
  return static_cast<double>(pstart_[n] + wstart_[n]) / static_cast<double>(n);
}

double SphFluid::kinetic_energy() const {
  double e = 0.0;
  for (std::size_t i = 0; i < fluid_.size(); ++i)
    e += fluid_.vx[i] * fluid_.vx[i] + fluid_.vy[i] * fluid_.vy[i];
  return 0.5 * mass_ * e;
}

Vec2 SphFluid::momentum() const {
  Vec2 m = Vec2::Zero();
  for (std::size_t i = 0; i < fluid_.size(); ++i) m += Vec2(fluid_.vx[i], fluid_.vy[i]);
  return mass_ * m;
}

double SphFluid::pressure_at(const Vec2& point) const {
  double sw = 0.0, swp = 0.0;
  const double c2 = options_.c0 * options_.c0;
  for (std::size_t i = 0; i < fluid_.size(); ++i) {
    double dx = point.x() - fluid_.x[i], dy = point.y() - fluid_.y[i];
    const Vec2 period = options_.domain_max - options_.domain_min;
    if (options_.periodic_x) dx -= period.x() * std::round(dx / period.x());
    if (options_.periodic_y) dy -= period.y() * std::round(dy / period.y());
    const double w = kernel_.W(std::sqrt(dx * dx + dy * dy)) * fluid_.vol[i];
    sw += w;
    swp += w * c2 * (fluid_.rho[i] - options_.rho0);
  }
  return sw > 0.0 ? swp / sw : 0.0;
}

double SphFluid::surge_front() const {
  // The largest x of the bulk, as the EMPS fluid's probe (pnd >= n0/2, pnd without i itself): a
  // particle whose neighbours' kernel sum (fluid and wall, without its own W(0), about a third
  // of sigma0) is below half the lattice's is spray, skipped. With W(0) counted, a lone particle
  // sliding on a floor would pass (0.54 sigma0: W(0) and the half-plane of dummies below it).
  const double w0 = kernel_.W(0.0), bulk = 0.5 * (sigma0_ - w0);
  double front = -std::numeric_limits<double>::max();
  for (std::size_t i = 0; i < fluid_.size(); ++i)
    if (kernel_sum(i) - w0 >= bulk) front = std::max(front, fluid_.x[i]);
  return front;
}

void SphFluid::save(State& s) const {
  fluid_.fields.save(s.fluid);
  walls_.fields.save(s.walls);
  s.t = t_, s.Dt = Dt_, s.elapsed = elapsed_, s.dt_acoustic = dt_acoustic_;
  s.step = step_, s.builds = builds_, s.sub = sub_, s.subs = subs_, s.removed = removed_;
}

void SphFluid::restore(const State& s) {
  fluid_.fields.restore(s.fluid);
  walls_.fields.restore(s.walls);
  t_ = s.t, Dt_ = s.Dt, elapsed_ = s.elapsed, dt_acoustic_ = s.dt_acoustic;
  step_ = s.step, builds_ = s.builds, sub_ = s.sub, subs_ = s.subs, removed_ = s.removed;
  build_pairs(false); // the restored advection step's pairs, from its build positions (checked)
  parallel_for(fluid_.size(), [&](std::size_t i) {
    fluid_.p[i] = options_.c0 * options_.c0 * (fluid_.rho[i] - options_.rho0);
  });
}

void SphFluid::write_state(StateArchive& a, const std::string& prefix) const {
  fluid_.fields.write_state(a, prefix + "fluid/");
  walls_.fields.write_state(a, prefix + "walls/");
  a.put(prefix + "clock", std::vector<double>{t_, Dt_, elapsed_, dt_acoustic_});
  a.put(prefix + "counters", std::vector<std::int64_t>{step_, builds_, sub_, subs_,
                                                       static_cast<std::int64_t>(removed_)});
}

void SphFluid::read_state(const StateArchive& a, const std::string& prefix) {
  const std::size_t nw = walls_.size();
  const auto& clock = a.reals(prefix + "clock", 4);
  const auto& counters = a.integers(prefix + "counters", 5);
  fluid_.fields.read_state(a, prefix + "fluid/");
  walls_.fields.read_state(a, prefix + "walls/");
  if (walls_.size() != nw)
    throw InputError("checkpoint: '" + prefix + "walls/' has " + std::to_string(walls_.size()) +
                     " wall particles, this scene has " + std::to_string(nw));
  t_ = clock[0], Dt_ = clock[1], elapsed_ = clock[2], dt_acoustic_ = clock[3];
  step_ = counters[0], builds_ = counters[1], sub_ = counters[2], subs_ = counters[3];
  removed_ = static_cast<std::size_t>(counters[4]);
  build_pairs(false); // as restore: the pairs were checked when first built
  parallel_for(fluid_.size(), [&](std::size_t i) {
    fluid_.p[i] = options_.c0 * options_.c0 * (fluid_.rho[i] - options_.rho0);
  });
}

Vec2 SphFluid::rkgc_gradient(std::size_t i, const std::vector<double>& psi) const {
  const auto& f = fluid_;
  Vec2 g = Vec2::Zero();
  for (std::uint32_t k = pstart_[i]; k < pstart_[i + 1]; ++k) {
    const std::uint32_t j = pj_[k];
    const double dWV = pdw_[k] * f.vol[j], gx = dWV * pex_[k], gy = dWV * pey_[k];
    g.x() += psi[i] * (f.b00[j] * gx + f.b01[j] * gy) + psi[j] * (f.b00[i] * gx + f.b01[i] * gy);
    g.y() += psi[i] * (f.b01[j] * gx + f.b11[j] * gy) + psi[j] * (f.b01[i] * gx + f.b11[i] * gy);
  }
  return g;
}

Vec2 SphFluid::plain_difference_gradient(std::size_t i, const std::vector<double>& psi) const {
  Vec2 g = Vec2::Zero();
  for (std::uint32_t k = pstart_[i]; k < pstart_[i + 1]; ++k) {
    const std::uint32_t j = pj_[k];
    const double s = (psi[j] - psi[i]) * pdw_[k] * fluid_.vol[j];
    g += s * Vec2(pex_[k], pey_[k]);
  }
  return g;
}

Vec2 SphFluid::corrected_difference_gradient(std::size_t i, const std::vector<double>& psi) const {
  const Vec2 g = plain_difference_gradient(i, psi);
  const auto& f = fluid_;
  return Vec2(f.b00[i] * g.x() + f.b01[i] * g.y(), f.b01[i] * g.x() + f.b11[i] * g.y());
}

} // namespace fsi::sph
