// The EMPS fluid stepped decomposed over MPI ranks (parallel::ParticleDecomposition) against the
// same fluid on one process, in 2-D (a water column sliding along the floor of an open tank of
// plane walls) and in 3-D (a block of water sliding along the floor of a closed box tank of
// triangles, into its corner), far enough for migrations and neighbour-list (halo) rebuilds.
// Rank 0 runs the one-process reference and broadcasts it; every rank compares its owned
// particles with it by id.
#include "cloud.hpp"
#include "fluid_emps/emps_fluid.hpp"
#include "geometry_erp/box_walls.hpp"
#include "geometry_erp/fill.hpp"
#include "parallel/particle_decomposition.hpp"
#include "particles/setup_block.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <thread>
#include <utility>

using namespace fsi;
using namespace fsi::parallel;

namespace {

/// A 0.2 m x 0.2 m column (2,500 particles, l0 = 4 mm) in an open 0.6 m x 0.4 m tank, every
/// particle starting at 1 m/s to the right and 0.2 m/s up or down by row: 3.2 mm in 80 steps of
/// 4e-5 s (Courant 0.2 at c = 20 m/s), five times the half skin (0.63 mm), across the RCB cuts.
struct DamBreak {
  static constexpr int D = 2;
  static constexpr double l0 = 0.004, dt = 4e-5;
  static constexpr int steps = 80;
  static constexpr double height = 0.2; ///< of the water, m
  erp::WallSet walls;
  std::vector<Vec2> positions, velocities;
  DamBreak() {
    walls.add_polyline(std::vector<Vec2>{{0.0, 0.4}, {0.0, 0.0}, {0.6, 0.0}, {0.6, 0.4}}, false, 0);
    positions =
        erp::fill_lattice({0, 0}, l0, {{{0, 0}, {0.2, 0}, {0.2, 0.2}, {0, 0.2}}}, {}, &walls);
    for (const Vec2& x : positions)
      velocities.emplace_back(1.0, std::lround(x.y() / l0) % 2 ? 0.2 : -0.2);
  }
  static emps::FluidOptions options() {
    emps::FluidOptions o;
    o.density = 1000.0;
    o.l0 = l0;
    o.sound_speed = 20.0;
    o.domain_min = {-0.1, -0.1};
    o.domain_max = {0.7, 0.5};
    o.viscosity = 1e-6;
    o.artificial_viscosity = 0.1;
    o.wall.contact.alpha_rep = 1e7;
    o.gravity = {0.0, -9.81};
    return o;
  }
};

/// A 0.16 m x 0.12 m x 0.12 m block (2,304 particles, l0 = 1 cm) in the corner x = y = z = 0 of
/// a closed 0.4 m x 0.3 m x 0.2 m box tank of 12 triangles, the scenes' wall model (`default`:
/// approach viscosity, far-side images left out, compressed wall density, artificial viscosity
/// 0.2, the wall-gap limit) with nu = 1e-6: every particle starts at 2 m/s along +x, away from
/// the wall x = 0 (the particles by the corner have one, two and three faces), and 0.2 m/s up or
/// down by layer: 12 mm in 60 steps of 1e-4 s (Courant 0.2 at c = 20 m/s), about eight times
/// the half skin (1.55 mm), across the RCB cuts.
struct BoxSlide {
  static constexpr int D = 3;
  static constexpr double l0 = 0.01, dt = 1e-4;
  static constexpr int steps = 60;
  static constexpr double height = 0.12; ///< of the water, m
  erp::TriangleWallSet walls;
  std::vector<Vec3> positions, velocities;
  BoxSlide() {
    erp::add_box_tank(walls, Vec3(0, 0, 0), Vec3(0.4, 0.3, 0.2), false, 0);
    for (int i = 0; i < 16; ++i)
      for (int j = 0; j < 12; ++j)
        for (int k = 0; k < 12; ++k) {
          positions.push_back(l0 * Vec3(i + 0.5, j + 0.5, k + 0.5));
          velocities.emplace_back(2.0, j % 2 ? 0.2 : -0.2, 0.0);
        }
  }
  static emps::FluidOptions3 options() {
    emps::FluidOptions3 o;
    emps::apply_wall_preset(o, emps::WallModel::standard);
    o.density = 1000.0;
    o.l0 = l0;
    o.sound_speed = 20.0;
    o.domain_min = {-0.05, -0.05, -0.05};
    o.domain_max = {0.45, 0.35, 0.25};
    o.viscosity = 1e-6;
    o.wall.contact.alpha_rep = 1e7;
    o.gravity = {0.0, -9.81, 0.0};
    return o;
  }
};

/// The fluid of `Scene` with its velocities by id (each fluid its own scene: its own walls): the
/// whole fill, started at once; or, given the ranks, this rank's block of it, started by
/// decompose() (as `mpirun -np P fsi run` builds it, particles/setup_block.hpp).
template <class Scene> struct Fluid {
  static constexpr int D = Scene::D;
  Scene scene;
  particles::BlockRange range{0, scene.positions.size()};
  particles::SetupBlock block;
  emps::BasicEmpsFluid<D> fluid{make()};
  Fluid() { start(); }
  explicit Fluid(const Communicator& comm)
      : range(particles::block_of(scene.positions.size(), comm.rank(), comm.size())),
        block{range.first, true}, fluid{make()} {
    start();
  }
  void start() {
    std::vector<VecD<D>> v;
    for (std::size_t i = 0; i < fluid.owned(); ++i)
      v.push_back(scene.velocities[fluid.particles().id[i]]);
    fluid.set_velocities(v);
  }
  std::vector<VecD<D>> part(const std::vector<VecD<D>>& all) const {
    const auto first = all.begin() + static_cast<std::ptrdiff_t>(range.first);
    return std::vector<VecD<D>>(first, first + static_cast<std::ptrdiff_t>(range.size()));
  }
  emps::BasicEmpsFluid<D> make() {
    if constexpr (D == 2)
      return {Scene::options(), part(scene.positions), scene.walls, block};
    else
      return {Scene::options(), part(scene.positions), scene.walls, true, block};
  }
};

/// The one-process run after the scene's steps, computed on rank 0 and broadcast: positions,
/// velocities and p of each particle by id, then its count, kinetic energy, largest speed, mean
/// neighbour count, largest pressure and neighbour-list builds.
template <class Scene> struct Reference {
  static constexpr int D = Scene::D;
  static constexpr std::size_t k = 2 * D + 1; // values a particle
  std::vector<double> values;
  std::size_t n;
  explicit Reference(const Communicator& comm, std::size_t count)
      : values(k * count + 6, 0.0), n(count) {
    if (comm.rank() == 0) {
      Fluid<Scene> one;
      auto& f = one.fluid;
      for (int s = 0; s < Scene::steps; ++s) f.advance(s * Scene::dt, Scene::dt);
      const auto& r = f.particles();
      for (std::size_t i = 0; i < r.size(); ++i) {
        double* v = &values[k * r.id[i]];
        for (int a = 0; a < D; ++a) v[a] = r.position[a][i], v[D + a] = r.velocity[a][i];
        v[2 * D] = r.p[i];
      }
      const double p_max = *std::max_element(r.p.begin(), r.p.end());
      const std::array<double, 6> summary = {static_cast<double>(r.size()),
                                             f.kinetic_energy(),
                                             f.max_speed(),
                                             f.mean_neighbours(),
                                             p_max,
                                             static_cast<double>(f.neighbour_builds())};
      std::copy(summary.begin(), summary.end(), values.begin() + static_cast<long>(k * n));
    }
    MPI_Bcast(values.data(), static_cast<int>(values.size()), MPI_DOUBLE, 0, comm.comm());
  }
  const double* particle(std::uint32_t id) const { return &values[k * id]; }
  double summary(int s) const { return values[k * n + static_cast<std::size_t>(s)]; }
};

/// The largest |a - b| of position (m), velocity (m/s) and pressure (Pa) over every rank's owned
/// particles against the reference, and the reference's largest pressure.
struct Difference {
  double x = 0, v = 0, p = 0, p_max = 0;
};

/// Runs `Scene` decomposed over every rank of `comm` and checks what holds at any rank count:
/// every id on exactly one rank, nothing removed, migrations and halo rebuilds during the run,
/// np = 1 bitwise equal to the one-process run, the global reductions.
template <class Scene> Difference run_decomposed(const Communicator& comm) {
  constexpr int D = Scene::D;
  Fluid<Scene> decomposed(comm);
  auto& fluid = decomposed.fluid;
  const auto n = static_cast<std::uint32_t>(decomposed.scene.positions.size());
  const Reference<Scene> reference(comm, n);
  ParticleDecomposition<D> decomposition(comm);
  fluid.decompose(decomposition);
  const long scattered = decomposition.emigrants(); // the first partition's
  // The first partition balanced the loads the fluid gave, 1 + the work of each particle's wall
  // faces (wall_work.hpp), to RCB's tolerance, not the counts.
  double load = 0.0, work = 0.0;
  for (std::size_t i = 0; i < fluid.owned(); ++i)
    load += 1.0 + fluid.particles().work[i], work += fluid.particles().work[i];
  const double loads = imbalance(comm, load);
  const double counts = imbalance(comm, static_cast<double>(fluid.owned()));
  CHECK(comm.sum(work) > 0.0);
  CHECK(loads <= 1.01);
  std::int64_t ghosts = 0;
  // A step without a halo rebuild sends each ghost only what the step reads of it: x and v at
  // the start, x at x*, p after the pressure (3 D + 1 doubles); every array (93 bytes in 2-D, 77
  // in 3-D) at each of the first two before issue 47's halo lists.
  constexpr double per_ghost = 8.0 * (3 * D + 1);
  int steady = 0;            // steps without a rebuild
  double steady_bytes = 0.0; // what they sent, every rank's
  std::int64_t steady_ghosts = 0;
  for (int s = 0; s < Scene::steps; ++s) {
    const long builds = decomposition.halo_builds();
    const double sent = comm.sum(decomposition.halo_bytes());
    const auto g = comm.sum(static_cast<std::int64_t>(fluid.particles().size() - fluid.owned()));
    fluid.advance(s * Scene::dt, Scene::dt);
    ghosts += static_cast<std::int64_t>(fluid.particles().size() - fluid.owned());
    if (decomposition.halo_builds() != builds) continue;
    ++steady;
    steady_bytes += comm.sum(decomposition.halo_bytes()) - sent;
    steady_ghosts += g;
  }

  // Every particle on exactly one rank; nothing removed.
  const auto& p = fluid.particles();
  const std::size_t owned = fluid.owned();
  const auto owner = test::owners_of(comm, p.id, owned, n);
  CHECK(comm.all(std::none_of(owner.begin(), owner.end(), [](int r) { return r < 0; })));
  CHECK(comm.sum(static_cast<std::int64_t>(owned)) == n);
  CHECK(reference.summary(0) == n);
  CHECK(comm.sum(static_cast<std::int64_t>(fluid.removed())) == 0);

  // Each owned particle against the reference particle of the same id.
  Difference d;
  for (std::size_t i = 0; i < owned; ++i) {
    const double* r = reference.particle(p.id[i]);
    for (int a = 0; a < D; ++a) {
      d.x = std::max(d.x, std::abs(p.position[a][i] - r[a]));
      d.v = std::max(d.v, std::abs(p.velocity[a][i] - r[D + a]));
    }
    d.p = std::max(d.p, std::abs(p.p[i] - r[2 * D]));
  }
  d = {comm.max(d.x), comm.max(d.v), comm.max(d.p), reference.summary(4)};
  ghosts = comm.sum(ghosts);
  const std::int64_t emigrants =
      comm.sum(static_cast<std::int64_t>(decomposition.emigrants() - scattered));
  if (comm.rank() == 0)
    std::printf("emps %dd np=%d: first partition's imbalance of loads %.4f, of counts %.4f; %u "
                "particles, %d steps, %ld migrations, %ld halo builds, %lld "
                "emigrants, %.0f ghosts a step (%.1f %% of the particles), %d steps without a "
                "rebuild: %.0f bytes, %.1f a ghost; max |dx| %.2e m, |dv| %.2e m/s, |dp| %.2e Pa "
                "(p max %.0f Pa)\n",
                D, comm.size(), loads, counts, n, Scene::steps, decomposition.migrations(),
                decomposition.halo_builds(), static_cast<long long>(emigrants),
                static_cast<double>(ghosts) / Scene::steps,
                100.0 * static_cast<double>(ghosts) / Scene::steps / n, steady, steady_bytes,
                steady_ghosts ? steady_bytes / static_cast<double>(steady_ghosts) : 0.0, d.x, d.v,
                d.p, d.p_max);
  // Exact: integers below 2^53. Every step but the rebuilds' keeps its halo; np = 1 has none.
  CHECK(steady >= Scene::steps / 2);
  CHECK(steady_bytes == per_ghost * static_cast<double>(steady_ghosts));
  if (comm.size() > 1) CHECK(steady_ghosts > 0);

  // The run did what the test is for: particles crossed the cuts during the run (not only at
  // the first partition), the list and halo were rebuilt (each rebuild migrates first).
  CHECK(decomposition.migrations() >= 3);
  CHECK(decomposition.halo_builds() >= 3);
  CHECK(reference.summary(5) >= 3);
  if (comm.size() > 1) CHECK(emigrants > 0);
  CHECK(d.p_max > 0.5 * 1000.0 * 9.81 * Scene::height); // half the hydrostatic rho g H

  if (comm.size() == 1) { // the same sums in the same order
    CHECK(d.x == 0.0);
    CHECK(d.v == 0.0);
    CHECK(d.p == 0.0);
  }

  // The global reductions: kinetic energy (a sum in another order) and the largest speed.
  CHECK_THAT(fluid.kinetic_energy(), Catch::Matchers::WithinRel(reference.summary(1), 1e-12));
  // |max_i |v_i| - max_i |v_i,ref|| <= max_i |v_i - v_i,ref| <= sqrt(D) d.v
  const double sqrt_d = D == 2 ? 1.5 : 1.8; // sqrt(2), sqrt(3) rounded up
  CHECK_THAT(fluid.max_speed(), Catch::Matchers::WithinAbs(reference.summary(2), sqrt_d * d.v));
  CHECK_THAT(fluid.mean_neighbours(), Catch::Matchers::WithinRel(reference.summary(3), 1e-14));
  return d;
}

/// The set-up of a decomposed fluid (issue 47): each rank builds its block of the fill only, at
/// most ceil(n / P) particles (no margin: the blocks hold floor or ceil of n / P, and nothing is
/// added before the first partition), every id 0 .. n - 1 on exactly one rank; decompose() then
/// completes the start, each particle's initial pnd and pressure those of the one-process start
/// (every rank builds that one too, whole: a few thousand particles) to round-off: returns the
/// largest |d pnd| / n0 and |d p| / (c^2 rho) over the ranks.
template <class Scene> std::pair<double, double> check_setup(const Communicator& comm) {
  constexpr int D = Scene::D;
  Fluid<Scene> block(comm);
  const auto& p = block.fluid.particles();
  const auto n = static_cast<std::uint32_t>(block.scene.positions.size());
  const auto ranks = static_cast<std::size_t>(comm.size());
  const auto held = static_cast<std::size_t>(comm.max(static_cast<std::int64_t>(p.size())));
  CHECK(held <= (n + ranks - 1) / ranks);
  const auto owner = test::owners_of(comm, p.id, p.size(), n);
  CHECK(comm.all(std::none_of(owner.begin(), owner.end(), [](int r) { return r < 0; })));

  Fluid<Scene> whole;
  const auto& w = whole.fluid.particles();
  REQUIRE(w.size() == n);
  std::vector<std::size_t> row(n);
  for (std::size_t i = 0; i < n; ++i) row[w.id[i]] = i;
  ParticleDecomposition<D> decomposition(comm);
  block.fluid.decompose(decomposition);
  double pnd = 0.0, pressure = 0.0;
  bool surface = true;
  for (std::size_t i = 0; i < block.fluid.owned(); ++i) {
    const std::size_t j = row[p.id[i]];
    pnd = std::max(pnd, std::abs(p.pnd[i] - w.pnd[j]));
    pressure = std::max(pressure, std::abs(p.p[i] - w.p[j]));
    // The flag is pnd < beta n0: equal unless the pnd lies within its round-off of the threshold.
    const bool at_threshold =
        std::abs(w.pnd[j] - Scene::options().beta * whole.fluid.n0()) <= 1e-13 * whole.fluid.n0();
    surface = surface && (at_threshold || p.surface[i] == w.surface[j]);
  }
  CHECK(comm.sum(static_cast<std::int64_t>(block.fluid.owned())) == n);
  CHECK(comm.all(surface));
  const auto o = Scene::options();
  const std::pair<double, double> d{comm.max(pnd) / whole.fluid.n0(),
                                    comm.max(pressure) /
                                        (o.sound_speed * o.sound_speed * o.density)};
  if (comm.rank() == 0)
    std::printf("emps %dd np=%d set-up: %u particles, at most %zu a rank before the partition; "
                "initial |d pnd| / n0 %.2e, |d p| / (c^2 rho) %.2e\n",
                D, comm.size(), n, held, d.first, d.second);
  if (comm.size() == 1) CHECK(d.first == 0.0); // the same sums in the same order
  return d;
}

} // namespace

TEST_CASE("a decomposed EMPS fluid is built from each rank's block of the fill", "[parallel]") {
  // Round-off bounds: a pnd is a sum of some 30 (2-D) to 120 (3-D) weights below 1 in another
  // order (the ranks' cell orders, ghosts last): a relative error of about 1e-15 of n0.
  for (const auto& d :
       {check_setup<DamBreak>(Communicator()), check_setup<BoxSlide>(Communicator())}) {
    CHECK(d.first <= 1e-13);
    CHECK(d.second <= 1e-13);
  }
}

TEST_CASE("EMPS on P ranks equals EMPS on one process, particle by particle", "[parallel]") {
  const Difference d = run_decomposed<DamBreak>(Communicator());
  // Across ranks the pair sums run in another order (cell order of each rank's own particles,
  // ghosts last): round-off. Measured at np = 2, 3, 4: |dx| <= 1.1e-16 m (an ulp of x ~ 0.1 m
  // is 1.4e-17), |dv| <= 5.7e-14 m/s, |dp| <= 1.7e-9 Pa = 2.8e-13 p_max (p = c^2 rho (pnd -
  // n0) / n0 with c^2 rho = 4e5 Pa: a relative round-off e of pnd is 4e5 e Pa). Bounds about
  // ten times those.
  CHECK(d.x <= 1e-15);
  CHECK(d.v <= 5e-13);
  CHECK(d.p <= 3e-12 * d.p_max);
}

TEST_CASE("3-D EMPS with triangle walls on P ranks equals it on one process", "[parallel]") {
  const Difference d = run_decomposed<BoxSlide>(Communicator());
  // Round-off as in 2-D, the wall terms' mirror sums over the cells (ghosts included) in
  // another order too. Measured at np = 2, 3, 4: |dx| <= 5.6e-17 m, |dv| <= 6.2e-15 m/s, |dp|
  // <= 5.5e-10 Pa = 5.9e-13 p_max (p max 923 Pa). Bounds about ten times those.
  CHECK(d.x <= 5e-16);
  CHECK(d.v <= 6e-14);
  CHECK(d.p <= 6e-12 * d.p_max);
}

// The step's timers net of the waits (issue 47, run.json `busy_seconds`): the last rank starts a
// step 1 s after the others, which wait for it in the step's first halo update; every rank's
// parts of the step stay those of a step of 2,500 particles (milliseconds; under half the delay
// on a loaded machine) and the others' 1 s goes to `waited`. Asserted on values reduced over
// the ranks, so rank 0 reports them.
TEST_CASE("the EMPS step's timers leave out the waits in collectives", "[parallel]") {
  const Communicator comm;
  Fluid<DamBreak> decomposed;
  auto& fluid = decomposed.fluid;
  ParticleDecomposition<2> decomposition(comm);
  fluid.decompose(decomposition);
  fluid.advance(0.0, DamBreak::dt);
  const emps::StepTimes before = fluid.times();
  comm.sum(0.0); // every rank in step
  const bool late = comm.rank() == comm.size() - 1;
  if (late) std::this_thread::sleep_for(std::chrono::seconds(1));
  fluid.advance(DamBreak::dt, DamBreak::dt);
  const emps::StepTimes& after = fluid.times();
  const double own = after.busy() - before.busy(), waited = after.waited - before.waited;
  const double inf = std::numeric_limits<double>::infinity();
  CHECK(comm.min(own) > 0.0);
  CHECK(comm.max(own) < 0.5);
  CHECK(comm.min(waited) >= 0.0);
  CHECK(comm.max(late ? waited : 0.0) < 0.5);
  if (comm.size() > 1) CHECK(comm.min(late ? inf : waited) >= 0.99);
}
