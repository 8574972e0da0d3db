// The fluid's state: copies for iterative coupling (save, restore) and checkpoints.
#include "fluid_emps/emps_fluid.hpp"

#include "fsi/core/error.hpp"
#include "fsi/core/state_archive.hpp"

#include <array>
#include <string>
#include <vector>

namespace fsi::emps {

template <int D> typename BasicEmpsFluid<D>::State BasicEmpsFluid<D>::save() const {
  State s{{}, step_, removed_, layout_, gap_dt_, gap_limited_steps_};
  particles_.fields.save(s.particles);
  return s;
}

template <int D> void BasicEmpsFluid<D>::restore(const State& s) {
  particles_.fields.restore(s.particles);
  step_ = s.step;
  removed_ = s.removed;
  gap_dt_ = s.gap_dt;
  gap_limited_steps_ = s.gap_limited_steps;
  if (s.layout != layout_) {
    layout_ = s.layout;
    neighbours_.invalidate();
  }
  if constexpr (D == 2) walls_.hits_layout = -1; // the hits belong to the abandoned step
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

template <int D>
void BasicEmpsFluid<D>::write_state(StateArchive& a, const std::string& prefix) const {
  particles_.fields.write_state(a, prefix);
  a.put_integer(prefix + "step", step_);
  a.put_integer(prefix + "removed", static_cast<std::int64_t>(removed_));
  a.put_integer(prefix + "layout", layout_);
  a.put_integer(prefix + "builds", builds_);
  a.put_real(prefix + "mean_neighbours", mean_neighbours_);
  if (options_.wall.gap_courant > 0) {
    a.put_real(prefix + "gap_dt", gap_dt_);
    a.put_integer(prefix + "gap_limited_steps", gap_limited_steps_);
  }
  // The list is rebuilt from its build positions on restart (same grid, same rows, same order).
  const auto built = static_cast<std::ptrdiff_t>(neighbours_.built());
  for (int axis = 0; axis < D; ++axis) {
    const std::vector<double>& b = neighbours_.build_positions(axis);
    a.put(prefix + "neighbours/" + build_key(axis),
          std::vector<double>(b.begin(), b.begin() + built));
  }
  if constexpr (D == 2) write_hits(a, prefix);
}

// Wall hits of the last x*, reused by the next viscous step while the layout is unchanged.
template <int D>
void BasicEmpsFluid<D>::write_hits(StateArchive& a, const std::string& prefix) const
    requires(D == 2) {
  const erp::WallHits& hits = walls_.hits;
  const bool hits_valid = walls_.hits_layout == layout_;
  a.put_integer(prefix + "hits/valid", hits_valid);
  if (!hits_valid) return;
  const std::string h = prefix + "hits/";
  a.put_ints(h + "crossed", hits.crossed);
  a.put(h + "a_wall", flatten(hits.a_wall));
  for (std::size_t k = 0; k < erp::max_faces; ++k) {
    const erp::FaceHits& f = hits.face[k];
    a.put_ints(h + face_key("segment", k), f.segment);
    a.put(h + face_key("t", k), f.t);
    a.put(h + face_key("r", k), f.r);
    a.put(h + face_key("x_wall", k), flatten(f.x_wall));
    a.put(h + face_key("n_wall", k), flatten(f.n_wall));
    a.put(h + face_key("v_wall", k), flatten(f.v_wall));
  }
}

template <int D>
void BasicEmpsFluid<D>::read_state(const StateArchive& a, const std::string& prefix) {
  particles_.fields.read_state(a, prefix);
  const std::size_t n = particles_.size();
  step_ = a.integer(prefix + "step");
  removed_ = static_cast<std::size_t>(a.integer(prefix + "removed"));
  layout_ = a.integer(prefix + "layout");
  builds_ = a.integer(prefix + "builds");
  mean_neighbours_ = a.real(prefix + "mean_neighbours");
  if (options_.wall.gap_courant > 0) {
    gap_dt_ = a.real(prefix + "gap_dt");
    gap_limited_steps_ = a.integer(prefix + "gap_limited_steps");
  }
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
    particles::Coords<D> xb;
    for (std::size_t axis = 0; axis < D; ++axis) xb[axis] = build[axis].data();
    grid_.bin(xb, n);
    if (!neighbours_.build(grid_, xb, n, r_e_ * (1.0 + options_.skin), capacity_,
                           options_.vector_kernels))
      throw InputError("checkpoint: the stored neighbour list overflows");
  }
  if constexpr (D == 2) read_hits(a, prefix);
}

template <int D>
void BasicEmpsFluid<D>::read_hits(const StateArchive& a,
                                  const std::string& prefix) requires(D == 2) {
  erp::WallHits& hits = walls_.hits;
  walls_.hits_layout = -1;
  if (a.integer(prefix + "hits/valid") == 0) return;
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

template auto BasicEmpsFluid<2>::save() const -> State;
template auto BasicEmpsFluid<3>::save() const -> State;
template void BasicEmpsFluid<2>::restore(const State&);
template void BasicEmpsFluid<3>::restore(const State&);
template void BasicEmpsFluid<2>::write_state(StateArchive&, const std::string&) const;
template void BasicEmpsFluid<3>::write_state(StateArchive&, const std::string&) const;
template void BasicEmpsFluid<2>::read_state(const StateArchive&, const std::string&);
template void BasicEmpsFluid<3>::read_state(const StateArchive&, const std::string&);

} // namespace fsi::emps
