// The fluid's state: copies for iterative coupling (save, restore) and checkpoints.
#include "fluid_emps/emps_fluid.hpp"

#include "fsi/core/error.hpp"
#include "fsi/core/state_archive.hpp"

#include <string>
#include <vector>

namespace fsi::emps {

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
/// The checkpoint names of face k's arrays: "x_wall", "x_wall2", ... (face 0 without a number).
std::string face_key(const std::string& name, std::size_t k) {
  return k == 0 ? name : name + std::to_string(k + 1);
}
} // namespace

void EmpsFluid::write_state(StateArchive& a, const std::string& prefix) const {
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
  a.put_ints(h + "crossed", hits_.crossed);
  a.put(h + "a_wall", flatten(hits_.a_wall));
  for (std::size_t k = 0; k < erp::max_faces; ++k) {
    const erp::FaceHits& f = hits_.face[k];
    a.put_ints(h + face_key("segment", k), f.segment);
    a.put(h + face_key("t", k), f.t);
    a.put(h + face_key("r", k), f.r);
    a.put(h + face_key("x_wall", k), flatten(f.x_wall));
    a.put(h + face_key("n_wall", k), flatten(f.n_wall));
    a.put(h + face_key("v_wall", k), flatten(f.v_wall));
  }
}

void EmpsFluid::read_state(const StateArchive& a, const std::string& prefix) {
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
  hits_.crossed = a.ints<unsigned char>(h + "crossed", m);
  hits_.a_wall = unflatten(a.reals(h + "a_wall", 2 * m));
  for (std::size_t k = 0; k < erp::max_faces; ++k) {
    erp::FaceHits& f = hits_.face[k];
    f.segment = a.ints<int>(h + face_key("segment", k), m);
    f.t = a.reals(h + face_key("t", k), m);
    f.r = a.reals(h + face_key("r", k), m);
    f.x_wall = unflatten(a.reals(h + face_key("x_wall", k), 2 * m));
    f.n_wall = unflatten(a.reals(h + face_key("n_wall", k), 2 * m));
    f.v_wall = unflatten(a.reals(h + face_key("v_wall", k), 2 * m));
  }
  hits_layout_ = layout_;
}

} // namespace fsi::emps
