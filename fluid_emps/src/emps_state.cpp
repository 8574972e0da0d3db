// The fluid's state: copies for iterative coupling (save, restore) and checkpoints.
#include "fluid_emps/emps_fluid.hpp"

#include "fsi/core/error.hpp"
#include "fsi/core/node_archive.hpp"
#include "fsi/core/state_archive.hpp"
#include "particles/state_rows.hpp"

#include <algorithm>
#include <array>
#include <string>
#include <type_traits>
#include <vector>

namespace fsi::emps {

// Decomposed (issue 47): the owned particles only, and restore() drops the ghosts and
// invalidates the list, so that the next step migrates and builds ghosts afresh: the step
// being redone may have rebuilt the halo, which then no longer matches the saved ghosts.
template <int D> typename BasicEmpsFluid<D>::State BasicEmpsFluid<D>::save() const {
  State s{{}, step_, removed_, layout_, gap_dt_, gap_limited_steps_};
  particles_.fields.save(s.particles, owned());
  if constexpr (D == 3)
    if (walls_.moving()) s.walls_before = walls_.before->walls.nodes();
  return s;
}

template <int D> void BasicEmpsFluid<D>::restore(const State& s) {
  const bool ghosts = decomposition_ != &local_; // processes' or periodic images
  if (ghosts) decomposition_->drop_ghosts(particles_.fields);
  particles_.fields.restore(s.particles);
  step_ = s.step;
  removed_ = s.removed;
  gap_dt_ = s.gap_dt;
  gap_limited_steps_ = s.gap_limited_steps;
  if (s.layout != layout_ || ghosts) {
    layout_ = s.layout;
    neighbours_.invalidate();
  }
  if constexpr (D == 2)
    walls_.hits_layout = -1; // the hits belong to the abandoned step
  else
    walls_.set_step_start(s.walls_before); // the walls at the redone step's start
}

namespace {
/// The checkpoint names of face k's arrays: "x_wall", "x_wall2", ... (face 0 without a number).
std::string face_key(const std::string& name, std::size_t k) {
  return k == 0 ? name : name + std::to_string(k + 1);
}

/// The checkpoint name of the neighbour list's build positions on an axis: "x_build", ...
std::string build_key(int axis) {
  return std::string(1, "xyz"[axis]) + "_build";
}
} // namespace

// One process: the arrays in the particles' order. Decomposed (collective): every process's
// owned particles gathered to process 0 in id order, the one-process format (issue 47), whose
// archive alone is whole; the counters are global.
template <int D>
void BasicEmpsFluid<D>::write_state(StateArchive& a, const std::string& prefix) const {
  const bool listed = decomposition_->all(neighbours_.built() > 0);
  bool hits = false;
  if constexpr (D == 2) hits = decomposition_->all(walls_.hits_layout == layout_);
  if (decomposed()) {
    StateArchive rows;
    write_rows(rows, prefix, listed, hits);
    particles::gather_rows(*decomposition_, rows, prefix + "id", a);
  } else {
    write_rows(a, prefix, listed, hits);
  }
  a.put_integer(prefix + "step", step_);
  a.put_integer(prefix + "removed",
                static_cast<std::int64_t>(decomposition_->sum(static_cast<double>(removed_))));
  a.put_integer(prefix + "layout", layout_);
  a.put_integer(prefix + "builds", builds_);
  a.put_real(prefix + "mean_neighbours", mean_neighbours_);
  if (options_.wall.gap_courant > 0) {
    a.put_real(prefix + "gap_dt", gap_dt_);
    a.put_integer(prefix + "gap_limited_steps", gap_limited_steps_);
  }
  if constexpr (D == 2)
    a.put_integer(prefix + "hits/valid", hits);
  else if (walls_.moving())
    put_nodes(a, prefix + "walls_before/", walls_.before->walls.nodes()); // the walls at t^n
}

// The per-particle arrays of the owned particles: the fields, the neighbour list's build
// positions (the list is rebuilt from them on restart: same grid, same rows, same order) when
// `listed`, the wall hits of the last x* (reused by the next viscous step) when `hits`.
template <int D>
void BasicEmpsFluid<D>::write_rows(StateArchive& a, const std::string& prefix, bool listed,
                                   bool hits) const {
  const std::size_t n = owned();
  particles_.fields.write_state(a, prefix, n);
  for (int axis = 0; axis < D; ++axis) {
    const std::vector<double>& b = neighbours_.build_positions(axis);
    a.put(prefix + "neighbours/" + build_key(axis),
          listed ? std::vector<double>(b.begin(), b.begin() + static_cast<std::ptrdiff_t>(n))
                 : std::vector<double>());
  }
  if constexpr (D == 2)
    if (hits) write_hits(a, prefix, n);
}

template <int D>
void BasicEmpsFluid<D>::write_hits(StateArchive& a, const std::string& prefix, std::size_t n) const
    requires(D == 2) {
  const erp::WallHits& hits = walls_.hits;
  const auto first = [n](const auto& v) {
    return std::remove_cvref_t<decltype(v)>(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(n));
  };
  const std::string h = prefix + "hits/";
  a.put_ints(h + "crossed", first(hits.crossed));
  a.put(h + "a_wall", flatten(first(hits.a_wall)));
  for (std::size_t k = 0; k < erp::max_faces; ++k) {
    const erp::FaceHits& f = hits.face[k];
    a.put_ints(h + face_key("segment", k), first(f.segment));
    a.put(h + face_key("t", k), first(f.t));
    a.put(h + face_key("r", k), first(f.r));
    a.put(h + face_key("x_wall", k), flatten(first(f.x_wall)));
    a.put(h + face_key("n_wall", k), flatten(first(f.n_wall)));
    a.put(h + face_key("v_wall", k), flatten(first(f.v_wall)));
  }
}

template <int D>
void BasicEmpsFluid<D>::read_state(const StateArchive& a, const std::string& prefix) {
  step_ = a.integer(prefix + "step");
  removed_ = static_cast<std::size_t>(a.integer(prefix + "removed"));
  layout_ = a.integer(prefix + "layout");
  builds_ = a.integer(prefix + "builds");
  mean_neighbours_ = a.real(prefix + "mean_neighbours");
  if (options_.wall.gap_courant > 0) {
    gap_dt_ = a.real(prefix + "gap_dt");
    gap_limited_steps_ = a.integer(prefix + "gap_limited_steps");
  }
  bool hits = false;
  if constexpr (D == 2) {
    hits = a.integer(prefix + "hits/valid") != 0;
  } else if (walls_.moving()) {
    erp::TriangleWallNodes before = walls_.before->walls.nodes(); // sized as the walls
    read_nodes(a, prefix + "walls_before/", before);
    walls_.set_step_start(before);
  }
  read_rows(a, prefix, hits);
  restored_ = true;
  started_ = true; // the checkpoint's pressures, not a start's
}

template <int D>
void BasicEmpsFluid<D>::read_rows(const StateArchive& a, const std::string& prefix, bool hits) {
  if (periodic_) periodic_->drop_ghosts(particles_.fields);
  particles_.fields.read_state(a, prefix);
  std::size_t n = particles_.size();
  std::array<std::vector<double>, D> build;
  build[0] = a.reals(prefix + "neighbours/" + build_key(0));
  for (int axis = 1; axis < D; ++axis)
    build[static_cast<std::size_t>(axis)] =
        a.reals(prefix + "neighbours/" + build_key(axis), build[0].size());
  neighbours_.invalidate();
  if (!build[0].empty()) {
    if (build[0].size() != n)
      throw InputError("checkpoint: '" + prefix +
                       "neighbours/x_build' does not match the particles");
    if (periodic_) n = restore_images(build);
    particles::Coords<D> xb;
    for (std::size_t axis = 0; axis < D; ++axis) xb[axis] = build[axis].data();
    grid_.bin(xb, n);
    if (!neighbours_.build(grid_, xb, n, r_e_ * (1.0 + options_.skin), capacity_,
                           options_.vector_kernels))
      throw InputError("checkpoint: the stored neighbour list overflows");
  }
  if constexpr (D == 2) {
    walls_.hits_layout = -1;
    if (hits) read_hits(a, prefix);
  }
}

template <int D>
void BasicEmpsFluid<D>::read_hits(const StateArchive& a,
                                  const std::string& prefix) requires(D == 2) {
  erp::WallHits& hits = walls_.hits;
  const std::string h = prefix + "hits/";
  const std::size_t m = a.integers(h + "segment").size();
  hits.crossed = a.ints<unsigned char>(h + "crossed", m);
  hits.a_wall = unflatten(a.reals(h + "a_wall", 2 * m));
  for (std::size_t k = 0; k < erp::max_faces; ++k) {
    erp::FaceHits& f = hits.face[k];
    f.segment = a.ints<int>(h + face_key("segment", k), m);
    f.t = a.reals(h + face_key("t", k), m);
    f.r = a.reals(h + face_key("r", k), m);
    f.x_wall = unflatten(a.reals(h + face_key("x_wall", k), 2 * m));
    f.n_wall = unflatten(a.reals(h + face_key("n_wall", k), 2 * m));
    f.v_wall = unflatten(a.reals(h + face_key("v_wall", k), 2 * m));
  }
  walls_.hits_layout = layout_;
}

// periodic_z: the images the run that wrote the checkpoint built at its last list build (those
// of the particles within reach of a face at their build positions), their current values and
// their build positions (the owner's, shifted), so the list is rebuilt as it was.
template <int D>
std::size_t BasicEmpsFluid<D>::restore_images(std::array<std::vector<double>, D>& build) {
  const std::size_t n = particles_.size();
  periodic_->build_images(particles_.fields, build[D - 1].data(), r_e_ * (1.0 + options_.skin));
  for (std::size_t axis = 0; axis < D; ++axis) {
    std::vector<double>& b = build[axis];
    b.resize(particles_.size());
    for (std::size_t k = 0; k < periodic_->ghosts(); ++k)
      b[n + k] = b[periodic_->source(k)] + (axis == D - 1 ? periodic_->shift(k) : 0.0);
  }
  return particles_.size();
}

// A restart under mpirun (issue 47): every process read the whole checkpoint (read_state) and
// keeps its block of it. Partitioned as the run that wrote it was at its last neighbour-list
// build: the migration and the halo at the stored build positions, so the ghosts cover every pair
// the list holds until its next rebuild; then each process takes its particles' rows of the
// checkpoint (fields, build positions, wall hits), and the next step neither rebuilds nor requeries
// before the run that wrote it did. Without a stored list: a fresh partition, as at a start.
template <int D> void BasicEmpsFluid<D>::scatter_restored() {
  ParticleSet& p = particles_;
  const std::size_t n = p.size();
  bool hits = false;
  if constexpr (D == 2) hits = walls_.hits_layout == layout_;
  StateArchive all; // every particle's rows, in the checkpoint's order
  write_rows(all, "", true, hits);
  std::uint32_t top = 0;
  for (std::size_t i = 0; i < n; ++i) top = std::max(top, p.id[i]);
  std::vector<std::size_t> row(std::size_t{top} + 1);
  for (std::size_t i = 0; i < n; ++i) row[p.id[i]] = i;
  for (int axis = 0; axis < D; ++axis)
    p.position[axis] = all.reals("neighbours/" + build_key(axis));
  particles::keep_block(p.fields, decomposition_->rank(), decomposition_->processes(), keep_);
  if (decomposition_->migrate(p.fields, p.position, &p.work)) ++layout_;
  decomposition_->build_ghosts(p.fields, p.position, r_e_ * (1.0 + options_.skin));
  std::vector<std::size_t> pick(p.size());
  for (std::size_t j = 0; j < pick.size(); ++j) pick[j] = row[p.id[j]];
  StateArchive mine;
  particles::select_rows(all, n, pick, mine);
  read_rows(mine, "", hits);
}

template auto BasicEmpsFluid<2>::save() const -> State;
template auto BasicEmpsFluid<3>::save() const -> State;
template void BasicEmpsFluid<2>::restore(const State&);
template void BasicEmpsFluid<3>::restore(const State&);
template void BasicEmpsFluid<2>::write_state(StateArchive&, const std::string&) const;
template void BasicEmpsFluid<3>::write_state(StateArchive&, const std::string&) const;
template void BasicEmpsFluid<2>::read_state(const StateArchive&, const std::string&);
template void BasicEmpsFluid<3>::read_state(const StateArchive&, const std::string&);
template void BasicEmpsFluid<2>::scatter_restored();
template void BasicEmpsFluid<3>::scatter_restored();

} // namespace fsi::emps
