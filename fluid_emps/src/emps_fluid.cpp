#include "fluid_emps/emps_fluid.hpp"

#include "fluid_emps/wall_terms.hpp"
#include "fsi/core/error.hpp"
#include "fsi/core/option_ranges.hpp"
#include "fsi/core/parallel.hpp"
#include "particles/kernels.hpp"
#include "step_timer.hpp"
#include "wall_work.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <utility>

namespace fsi::emps {

namespace {

constexpr std::size_t none = std::numeric_limits<std::size_t>::max();

std::size_t first_index(std::size_t n, const auto& bad) {
  return parallel_reduce_balanced(
      n, none, [&](std::size_t i) { return bad(i) ? i : none; },
      [](std::size_t a, std::size_t b) { return std::min(a, b); });
}

template <int D> std::string where(const BasicParticles<D>& p, std::size_t i, long step, double t) {
  std::ostringstream out;
  out << "particle " << p.id[i] << " at (";
  for (int a = 0; a < D; ++a) out << (a ? ", " : "") << p.position[a][i];
  out << ") m, step " << step << ", t = " << t << " s";
  return out.str();
}

template <int D> const BasicFluidOptions<D>& validated(const BasicFluidOptions<D>& options) {
  BasicFluidOptions<D> o = options;
  RangeChecker ranges("fluid.");
  visit_options(o, ranges); // the declared ranges of every key
  auto fail = [](const std::string& what) { throw InputError("fluid: " + what); };
  if (!(o.domain_max.array() > o.domain_min.array()).all()) fail("the domain box is empty");
  if (!(o.skin > 0 && o.skin < 1)) fail("skin must be in (0, 1)");
  // The images reach one period: the list's reach r_e (1 + skin) must not exceed it.
  if (o.periodic_z && D != 3) fail("periodic_z is for 3-D fluids");
  if (o.periodic_z && o.domain_max[D - 1] - o.domain_min[D - 1] < o.r_e() * (1.0 + o.skin))
    fail("periodic_z: the period (the domain's depth) is shorter than r_e (1 + skin)");
  return options;
}

/// |v_i|^2 summed over the axes in order.
template <int D> double norm2(const BasicParticles<D>& p, std::size_t i) {
  double s = p.velocity[0][i] * p.velocity[0][i];
  for (int a = 1; a < D; ++a) s += p.velocity[a][i] * p.velocity[a][i];
  return s;
}

} // namespace

PlaneWalls::PlaneWalls(const FluidOptions& options, double n0, erp::WallSet& walls,
                       Particles& particles, const particles::CellGrid& grid)
    : locator(erp::make_wall_locator(walls, options.r_e())),
      terms(options, n0, walls, particles, grid, hits) {
  locator->set_corner_faces(options.wall.corner_faces);
  for (std::size_t k = 0; k < erp::max_faces; ++k)
    viscous[k] =
        particles::add_vector<2>(particles.fields, "wall_viscous" + std::to_string(k), false);
}

template <int D>
BasicEmpsFluid<D>::BasicEmpsFluid(const Options& options, const std::vector<Vec>& positions,
                                  erp::WallSet& walls,
                                  const particles::SetupBlock& block) requires(D == 2)
    : options_(validated(options)), walls_(options_, n0_, walls, particles_, grid_) {
  start(positions, block);
}

SpaceWalls::SpaceWalls(const FluidOptions3& options, double n0, const erp::TriangleWallSet& walls,
                       bool walls_move, const Particles3& particles,
                       const particles::BasicCellGrid<3>& grid)
    : locator(walls, options.r_e()), terms(options, n0, particles, grid, hits, convex),
      corner_faces(options.wall.corner_faces), convex_corners(options.wall.convex_corners) {
  if (walls_move) before.emplace(walls, options.r_e());
  // Not in 3-D yet: the two 2-D-only wall options are refused, not ignored.
  if (options.wall.contact.model == WallContact::viscous)
    throw InputError("fluid.wall_contact: 'viscous' is not available in 3-D yet");
  if (options.wall.mirror.pressure == WallPressure::neighbours)
    throw InputError("fluid.wall_pressure: 'neighbours' is not available in 3-D yet");
}

void SpaceWalls::set_step_start(const erp::TriangleWallNodes& nodes) {
  if (!moving()) return;
  before->walls.nodes() = nodes;
  before->walls.update();
  before->locator.update();
}

template <int D>
BasicEmpsFluid<D>::BasicEmpsFluid(const Options& options, const std::vector<Vec>& positions,
                                  const erp::TriangleWallSet& walls, bool walls_move,
                                  const particles::SetupBlock& block) requires(D == 3)
    : options_(validated(options)), walls_(options_, n0_, walls, walls_move, particles_, grid_) {
  start(positions, block);
}

template <int D>
void BasicEmpsFluid<D>::start(const std::vector<Vec>& positions,
                              const particles::SetupBlock& block) {
  const std::size_t n = positions.size();
  particles_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    for (int a = 0; a < D; ++a) particles_.position[a][i] = positions[i][a];
    particles_.id[i] = static_cast<std::uint32_t>(block.first + i);
  }
  // Row capacity: twice the lattice sites within (1 + skin) r_e, and a margin.
  const double reach = (1.0 + options_.skin) * options_.re_over_l0;
  const double sites = D == 2 ? std::numbers::pi * reach * reach
                              : 4.0 / 3.0 * std::numbers::pi * reach * reach * reach;
  capacity_ = static_cast<std::size_t>(std::ceil(2.0 * sites)) + 16;
  if (options_.periodic_z) // the images of the particles near the period's faces are the ghosts
    decomposition_ = &periodic_.emplace(D - 1, options_.domain_min[D - 1],
                                        options_.domain_max[D - 1] - options_.domain_min[D - 1],
                                        particles_.position);
  remove_outside();
  started_ = !block.deferred;
  if (!started_) return query_walls(); // the block's hits until decompose() starts it
  refresh_neighbours({}, true, 0, 0.0);
  query_walls();
  density_and_pressure();
}

// Initial damping phase (quiet hydrostatic starts): v <- v exp(-kappa dt) with a rate
// kappa = 20/T_d (1 - t/T_d) that fades to zero at T_d, so the run continues undamped.
template <int D> void BasicEmpsFluid<D>::damp(double t, double dt) {
  const double T = options_.damping_time;
  if (T <= 0 || t >= T) return;
  const double factor = std::exp(-20.0 / T * (1.0 - t / T) * dt);
  const std::array<double*, D> v = components(particles_.velocity);
  parallel_for(owned(), [&](std::size_t i) {
    for (std::size_t a = 0; a < D; ++a) v[a][i] *= factor;
  });
}

template <int D>
void BasicEmpsFluid<D>::refresh_neighbours(const particles::FieldList& changed, bool allow_reorder,
                                           long step, double t) {
  Timer<D> timer(times_.neighbours, times_, *decomposition_);
  ParticleSet& p = particles_;
  decomposition_->update_ghosts(p.fields, changed);
  const bool valid = neighbours_.valid(p.position.coords(), p.size(), 0.5 * options_.skin * r_e_);
  if (decomposition_->all(valid)) return;
  // Ghosts off, the owned particles to their regions' processes (nothing serial).
  if (decomposition_->migrate(p.fields, p.position, &p.work)) ++layout_;
  const std::size_t owned = p.size();
  grid_.bin(p.position.coords(), owned);
  if (allow_reorder && builds_ % std::max(1, options_.reorder_interval) == 0) {
    p.permute(grid_.order(), scratch_);
    ++layout_;
    grid_.bin(p.position.coords(), owned);
  }
  // Ghosts within reach of an owned particle until the next build: r_e + the skin.
  const double reach = r_e_ * (1.0 + options_.skin);
  decomposition_->build_ghosts(p.fields, p.position, reach);
  const std::size_t n = p.size();
  if (n != owned) grid_.bin(p.position.coords(), n);
  ++builds_;
  // Decomposed: the rows are truncated, and the step goes on to its next reduction, which stops
  // every process (particles::Decomposition::fail).
  if (!neighbours_.build(grid_, p.position.coords(), n, reach, capacity_, options_.vector_kernels))
    decomposition_->fail("fluid: more than " + std::to_string(capacity_) + " neighbours at " +
                         where(p, neighbours_.overflow(), step, t) +
                         " (particles clustered: the step is likely unstable)");
}

template <int D> void BasicEmpsFluid<D>::query_walls([[maybe_unused]] bool step_start) {
  Timer<D> timer(times_.walls, times_, *decomposition_);
  if constexpr (D == 2) {
    walls_.locator->query(std::span<const double>(particles_.x),
                          std::span<const double>(particles_.y), walls_.hits);
    walls_.hits_layout = layout_;
  } else {
    const std::span<const double> x(particles_.position[0]), y(particles_.position[1]),
        z(particles_.position[2]);
    SpaceHits& hits = walls_.hits;
    const erp::TriangleLocator& locator = step_start ? walls_.at_step_start() : walls_.locator;
    locator.query(x, y, z, hits[0]);
    if (walls_.corner_faces) {
      locator.corner_faces(x, y, z, hits);
    } else {
      for (std::size_t k = 1; k < max_faces3; ++k) {
        hits[k].resize(x.size());
        std::fill(hits[k].triangle.begin(), hits[k].triangle.end(), -1);
      }
    }
    if (walls_.convex_corners) locator.convex_faces(x, y, z, hits, walls_.convex);
  }
  if (decomposed()) wall_work<D>(walls_, owned(), particles_.work); // the next migration's load
}

template <int D> void BasicEmpsFluid<D>::check_crossed(long step, double t) const {
  const auto crossed_and_wall = [&] {
    if constexpr (D == 2)
      return std::pair(&walls_.hits.crossed, &walls_.hits.face[0].segment);
    else
      return std::pair(&walls_.hits[0].crossed, &walls_.hits[0].triangle);
  }();
  const auto* crossed = crossed_and_wall.first;
  const auto* wall = crossed_and_wall.second;
  const std::size_t i = first_index(owned(), [&](std::size_t k) { return (*crossed)[k] != 0; });
  if (i != none)
    decomposition_->fail("fluid: " + where(particles_, i, step, t) + " is behind wall " +
                         (D == 2 ? "segment " : "triangle ") + std::to_string((*wall)[i]) +
                         " (try a smaller time step or a larger alpha_rep)");
  // Decomposed: every process stops here (no wall terms of a crossed particle); the owner's
  // message, and any earlier fail() of the step, reach every process.
  decomposition_->agree();
}

template <int D> void BasicEmpsFluid<D>::advance(double t, double dt) {
  ParticleSet& p = particles_;
  {
    Timer<D> timer(times_.walls, times_, *decomposition_);
    if constexpr (D == 2)
      walls_.locator->update();
    else if (walls_.moving())
      walls_.locator.update();
  }
  const Vec g = options_.gravity;
  // Each halo update sends what the step reads of a ghost j before the next one (a rebuild sends
  // every array): at the start x^n and v^n (the list's validity, the wall hits, the viscous sums
  // of eqs. 11, 24 and the closing pairs), at x* the positions (the list's validity, the wall
  // hits, the pnd sums of eqs. 9, 20), then p (density_and_pressure). pnd, the surface flags and
  // the wall forces are read at owned rows only; id never changes.
  particles::FieldList step_start, moved;
  for (int a = 0; a < D; ++a)
    step_start.add(p.position[a]).add(p.velocity[a]), moved.add(p.position[a]);
  refresh_neighbours(step_start, true, step_ + 1, t);
  const std::size_t n = owned();
  // The viscous loop writes every particle's viscous wall forces; without it they are zero.
  const bool viscous = options_.viscous_loop();
  if constexpr (D == 2)
    if (!viscous)
      for (const auto& v : walls_.viscous)
        for (int a = 0; a < 2; ++a) std::fill_n(v[a].begin(), n, 0.0);
  if (viscous) {
    // The wall hits of the last step's x* serve x^n (which differs by dt^2 |grad p| / rho, and
    // they see the walls at t^n) unless particles were reordered or removed since.
    // In 3-D the hits are taken at x^n with the walls at t^n (SpaceWalls::before).
    if constexpr (D == 2) {
      if (walls_.hits_layout != layout_) query_walls();
    } else {
      query_walls(true);
    }
    viscosity();
  }
  {
    Timer<D> timer(times_.other, times_, *decomposition_);
    const std::array<double*, D> x = components(p.position), v = components(p.velocity);
    const double* visc = scratch_.data();
    parallel_for(n, [&](std::size_t i) { // v* = v + dt (nu <lap v> + g), x* = x + dt v* (eq. 13)
      for (std::size_t a = 0; a < D; ++a) {
        if (viscous) v[a][i] += dt * visc[D * i + a];
        v[a][i] += dt * g[static_cast<Eigen::Index>(a)];
        x[a][i] += dt * v[a][i];
      }
    });
  }
  check_finite(step_ + 1, t + dt); // v*, x* (before they are binned)
  refresh_neighbours(moved, false, step_ + 1, t + dt);
  query_walls();
  check_crossed(step_ + 1, t + dt);
  density_and_pressure();
  pressure_gradient(dt);
  if (options_.wall.gap_courant > 0) {
    if (dt >= gap_dt_) ++gap_limited_steps_;
    gap_dt_ = wall_gap_dt();
  }
  ++step_;
  if constexpr (D == 3)
    if (viscous) walls_.set_step_start(walls_.locator.walls().nodes()); // t^n of the next step
  Timer<D> timer(times_.other, times_, *decomposition_);
  damp(t, dt);
  check_finite(step_, t + dt);
  remove_outside();
}

template <int D> void BasicEmpsFluid<D>::check_finite(long step, double t) const {
  const ParticleSet& p = particles_;
  const std::size_t bad = first_index(owned(), [&](std::size_t i) {
    double s = p.p[i];
    for (int a = 0; a < D; ++a) s += p.position[a][i] + p.velocity[a][i];
    return !std::isfinite(s);
  });
  // Decomposed: the next reduction (the neighbour list's validity, the count outside the domain)
  // stops every process; nothing before it bins or migrates the non-finite positions.
  if (bad != none)
    decomposition_->fail("fluid: non-finite position, velocity or pressure at " +
                         where(p, bad, step, t));
}

template <int D> void BasicEmpsFluid<D>::remove_outside() {
  ParticleSet& p = particles_;
  const Vec lo = options_.domain_min, hi = options_.domain_max;
  keep_.resize(owned());
  const std::size_t outside = parallel_reduce(
      owned(), std::size_t{0},
      [&](std::size_t i) {
        bool in = true;
        for (int a = 0; a < D - (options_.periodic_z ? 1 : 0); ++a) // z wraps: never out
          in = in && p.position[a][i] >= lo[a] && p.position[a][i] <= hi[a];
        keep_[i] = in;
        return std::size_t{in ? 0u : 1u};
      },
      [](std::size_t a, std::size_t b) { return a + b; });
  if (decomposition_->sum(static_cast<double>(outside)) == 0) return;
  decomposition_->drop_ghosts(p.fields); // every process: the ghost layout ends here
  removed_ += p.compact(keep_);
  ++layout_;
  neighbours_.invalidate();
}

template <int D> double BasicEmpsFluid<D>::kinetic_energy() const {
  const double m = options_.density * options_.volume();
  return decomposition_->sum(parallel_reduce(
      owned(), 0.0, [&](std::size_t i) { return 0.5 * m * norm2(particles_, i); },
      [](double a, double b) { return a + b; }));
}

template <int D> double BasicEmpsFluid<D>::max_speed() const {
  return std::sqrt(decomposition_->max(parallel_reduce(
      owned(), 0.0, [&](std::size_t i) { return norm2(particles_, i); },
      [](double a, double b) { return std::max(a, b); })));
}

template <int D> void BasicEmpsFluid<D>::decompose(particles::Decomposition<D>& decomposition) {
  if (periodic_)
    throw InputError("fluid: periodic_z is not yet supported over processes (issue 47)");
  decomposition_ = &decomposition;
  if (std::exchange(restored_, false)) {         // every process read the whole checkpoint
    if (decomposition.rank() != 0) removed_ = 0; // the checkpoint's count, kept on process 0
    if (neighbours_.built() == particles_.size()) return scatter_restored();
  }
  if (started_) // the whole fluid (built whole, or a checkpoint): this process's block of it
    particles::keep_block(particles_.fields, decomposition.rank(), decomposition.processes(),
                          keep_);
  neighbours_.invalidate();
  query_walls(); // this block's hits, whose wall work (decomposed now) weighs the first partition
  refresh_neighbours({}, true, step_, 0.0);                   // the first migration and halo
  query_walls();                                              // the ghosts' hits
  if (!std::exchange(started_, true)) density_and_pressure(); // a block's initial pressures
}

template <int D> void BasicEmpsFluid<D>::set_velocities(const std::vector<Vec>& v) {
  if (v.size() != owned()) // the images take theirs at the next halo update
    throw InputError("fluid: " + std::to_string(v.size()) + " initial velocities for " +
                     std::to_string(owned()) + " particles");
  for (std::size_t i = 0; i < v.size(); ++i)
    for (int a = 0; a < D; ++a) particles_.velocity[a][i] = v[i][a];
}

// The wall-gap limit of the next step (WallTerms::gap_dt), with the step's last position
// correction (scratch_ still holds it).
template <int D> double BasicEmpsFluid<D>::wall_gap_dt() const {
  return decomposition_->min(parallel_reduce(
      owned(), std::numeric_limits<double>::infinity(),
      [&](std::size_t i) {
        if constexpr (D == 2)
          return walls_.terms.gap_dt(i, scratch_[2 * i], scratch_[2 * i + 1]);
        else
          return walls_.terms.gap_dt(
              i, Vec3(scratch_[3 * i], scratch_[3 * i + 1], scratch_[3 * i + 2]));
      },
      [](double a, double b) { return std::min(a, b); }));
}

template <int D> double BasicEmpsFluid<D>::stable_dt(double courant) const {
  double dt = courant * options_.l0 / (options_.sound_speed + max_speed());
  // v* = v + dt a_visc (eq. 13) is forward Euler: stable while dt times the viscous terms'
  // largest rate is at most 2. On the lattice that rate is 2d/(lambda0 n0) times nu P_lap for
  // eq. 11 (and eq. 24: a no-slip mirror continues the lattice's modes across a flat wall) plus
  // alpha c l0 P_closing for the closing-pair viscosities (their pairs across a wall continue the
  // lattice as the ghosts' velocity R v_j does), every closing pair taken at the largest alpha.
  const double rate =
      2.0 * D / (lambda0_ * n0_) *
      (options_.viscosity * laplacian_peak_ +
       options_.pair_viscosity_alpha() * options_.sound_speed * options_.l0 * closing_peak_);
  if (rate > 0) dt = std::min(dt, 2.0 / rate);
  if (options_.wall.gap_courant > 0) dt = std::min(dt, gap_dt_);
  return dt;
}

template BasicEmpsFluid<2>::BasicEmpsFluid(const Options&, const std::vector<Vec>&, erp::WallSet&,
                                           const particles::SetupBlock&);
template BasicEmpsFluid<3>::BasicEmpsFluid(const Options&, const std::vector<Vec>&,
                                           const erp::TriangleWallSet&, bool,
                                           const particles::SetupBlock&);
template void BasicEmpsFluid<2>::advance(double, double);
template void BasicEmpsFluid<3>::advance(double, double);
template void BasicEmpsFluid<2>::decompose(particles::Decomposition<2>&);
template void BasicEmpsFluid<3>::decompose(particles::Decomposition<3>&);
template void BasicEmpsFluid<2>::set_velocities(const std::vector<Vec>&);
template void BasicEmpsFluid<3>::set_velocities(const std::vector<Vec>&);
template double BasicEmpsFluid<2>::stable_dt(double) const;
template double BasicEmpsFluid<3>::stable_dt(double) const;
template double BasicEmpsFluid<2>::kinetic_energy() const;
template double BasicEmpsFluid<3>::kinetic_energy() const;
template double BasicEmpsFluid<2>::max_speed() const;
template double BasicEmpsFluid<3>::max_speed() const;

} // namespace fsi::emps
