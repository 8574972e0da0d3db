#pragma once
// F (eq. 66) of the SPH fluid on its structures' boundary points, in 2-D (InterfaceBoundary) and
// 3-D (InterfaceBoundary3), with sub-cycling: one coupler step of the interface motion from its
// state at the fluid's time (start_) to the one given (end_), crossed by the fluid's own acoustic
// steps. Per acoustic step the nodes move on the line between the two, the boundary points follow
// them (place), with the step's mean velocity and the coupler step's mean acceleration
// (v_end - v_start) / Dt (fluid.interface_acceleration; else zero) as the wall's time-averaged
// velocity and acceleration (eq. 17). The loads are the points' impulse over the coupler step /
// Dt, distributed to the nodes: the structure receives exactly the momentum the fluid lost to it.
#include "coupling/interface.hpp"
#include "fluid_sph/interface_boundary.hpp"
#include "fluid_sph/interface_boundary3.hpp"
#include "fluid_sph/sph_fluid.hpp"
#include "fsi/core/error.hpp"
#include "fsi/core/state_archive.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <type_traits>
#include <vector>

namespace fsi::app::sph_plugin {

template <int D>
using InterfaceBoundaryD =
    std::conditional_t<D == 2, sph::InterfaceBoundary, sph::InterfaceBoundary3>;

template <int D> class BoundaryAdapter final : public coupling::BasicFluidSolver<D> {
public:
  using Vec = VecD<D>;
  using Motion = coupling::BasicInterfaceMotion<D>;
  using Loads = coupling::BasicInterfaceLoads<D>;

  /// `interface_x`: each interface's nodes where its points are now (moved here; the fluid's
  /// guard reads them); the boundary points are the fluid's wall particles from `first_point` on.
  BoundaryAdapter(sph::BasicSphFluid<D>& fluid, const std::vector<InterfaceBoundaryD<D>>& bs,
                  std::vector<std::vector<Vec>>& interface_x, std::size_t first_point,
                  bool interface_acceleration)
      : fluid_(fluid), bs_(bs), interface_x_(interface_x), first_point_(first_point),
        mean_a_(interface_acceleration) {
    for (const auto& b : bs) {
      offset_.push_back(nodes_);
      nodes_ += b.mesh().node_count();
      points_ += b.size();
    }
    for (const auto& b : bs)
      start_.x.insert(start_.x.end(), b.mesh().X0.begin(), b.mesh().X0.end());
    start_.v.assign(nodes_, Vec::Zero());
    start_.a.assign(nodes_, Vec::Zero());
    end_ = start_;
    loads_ = Loads::zeros(nodes_);
    a_.resize(bs.size());
  }
  void initialize() override {}
  void set_interface_motion(const Motion& m) override {
    if (m.size() != nodes_)
      throw RunError("fluid_sph: interface motion of " + std::to_string(m.size()) +
                     " nodes, the fluid's interfaces have " + std::to_string(nodes_));
    end_ = m;
  }
  void advance(double t, double dt) override;
  const Loads& interface_loads() const override { return loads_; }
  void save_state() override {
    fluid_.save(saved_);
    saved_start_ = start_;
  }
  void restore_state() override {
    fluid_.restore(saved_);
    start_ = saved_start_;
  }
  std::optional<double> stable_dt() const override { return fluid_.advection_dt(); }
  /// The fluid under "fluid/", the interface motion at the fluid's time under
  /// "fluid/interface/motion" (x, v, a per node).
  void write_state(StateArchive& archive) const override {
    fluid_.write_state(archive, "fluid/");
    if (nodes_ == 0) return;
    std::vector<double> m;
    m.reserve(3 * D * nodes_);
    for (std::size_t k = 0; k < nodes_; ++k)
      for (const auto* q : {&start_.x[k], &start_.v[k], &start_.a[k]})
        m.insert(m.end(), q->data(), q->data() + D);
    archive.put("fluid/interface/motion", m);
  }
  void read_state(const StateArchive& archive) override {
    fluid_.read_state(archive, "fluid/");
    if (nodes_ == 0) return;
    const auto& m = archive.reals("fluid/interface/motion", 3 * D * nodes_);
    for (std::size_t k = 0; k < nodes_; ++k)
      for (int c = 0; c < D; ++c) {
        start_.x[k][c] = m[3 * D * k + c];
        start_.v[k][c] = m[3 * D * k + D + c];
        start_.a[k][c] = m[3 * D * k + 2 * D + c];
      }
  }

private:
  sph::BasicSphFluid<D>& fluid_;
  const std::vector<InterfaceBoundaryD<D>>& bs_;
  std::vector<std::vector<Vec>>& interface_x_;
  std::size_t first_point_;
  bool mean_a_;
  std::vector<std::size_t> offset_; ///< first coupler node of each interface
  std::size_t nodes_ = 0, points_ = 0;
  Motion start_, end_, saved_start_;
  Loads loads_;
  typename sph::BasicSphFluid<D>::State saved_;
  // Work arrays, sized once.
  std::vector<std::vector<Vec>> a_;
  std::vector<Vec> nodal_a_, position_, normal_, point_a_, impulse_, nodal_f_;
};

template <int D> void BoundaryAdapter<D>::advance(double t, double dt) {
  const double t_end = t + dt, inv_dt = 1.0 / dt;
  nodal_a_.resize(nodes_);
  // The wall acceleration of eq. 16's dummy pressure: the step's mean (v_end - v_start) / Dt
  // with fluid.interface_acceleration, else zero (docs/fluid_sph.md: explicit coupling with a
  // light structure feeds it back unstably).
  for (std::size_t k = 0; k < nodes_; ++k)
    nodal_a_[k] = mean_a_ ? Vec((end_.v[k] - start_.v[k]) * inv_dt) : Vec::Zero();
  for (std::size_t j = 0; j < bs_.size(); ++j) {
    const auto first = nodal_a_.begin() + static_cast<std::ptrdiff_t>(offset_[j]);
    a_[j].assign(first, first + static_cast<std::ptrdiff_t>(bs_[j].mesh().node_count()));
  }
  impulse_.assign(points_, Vec::Zero());
  sph::BasicWallParticles<D>& w = fluid_.moved_walls();
  while (fluid_.time() < t_end - 1e-12 * std::max(1.0, std::abs(t_end))) {
    const double h = std::min(fluid_.next_dt(), t_end - fluid_.time());
    const double s = std::min(1.0, (fluid_.time() + h - t) * inv_dt), inv_h = 1.0 / h;
    std::size_t a = first_point_;
    for (std::size_t j = 0; j < bs_.size(); ++j) {
      const std::size_t n = bs_[j].mesh().node_count();
      std::vector<Vec>& x = interface_x_[j];
      for (std::size_t k = 0; k < n; ++k)
        x[k] = (1.0 - s) * start_.x[offset_[j] + k] + s * end_.x[offset_[j] + k];
      bs_[j].place(x, position_, normal_);
      bs_[j].interpolate(a_[j], point_a_);
      for (std::size_t p = 0; p < bs_[j].size(); ++p, ++a) {
        for (int c = 0; c < D; ++c) {
          w.v[c][a] = (position_[p][c] - w.x[c][a]) * inv_h; // mean over the acoustic step (eq. 17)
          w.a[c][a] = point_a_[p][c];
          w.x[c][a] = position_[p][c];
          w.n[c][a] = normal_[p][c];
        }
      }
    }
    fluid_.advance(h);
    for (std::size_t p = 0; p < points_; ++p)
      impulse_[p] += fluid_.wall_force(first_point_ + p) * h;
  }
  std::size_t first = 0;
  for (std::size_t j = 0; j < bs_.size(); ++j) {
    position_.assign(impulse_.begin() + static_cast<std::ptrdiff_t>(first),
                     impulse_.begin() + static_cast<std::ptrdiff_t>(first + bs_[j].size()));
    for (auto& q : position_) q *= inv_dt; // mean force over the coupler step
    bs_[j].distribute(position_, nodal_f_);
    std::copy(nodal_f_.begin(), nodal_f_.end(),
              loads_.f.begin() + static_cast<std::ptrdiff_t>(offset_[j]));
    first += bs_[j].size();
  }
  start_ = end_;
}

} // namespace fsi::app::sph_plugin
