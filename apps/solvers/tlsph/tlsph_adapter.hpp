#pragma once
// The coupler's S (eq. 67 of the EMPS paper; eq. 12's a^{F:S} of the RKGC paper) on a TL-SPH part
// in D = 2 (TlsphModel, the outline's edges) or 3 (TlsphModel3, the box's faces): nodal loads on
// the interface nodes' particles in, the nodes' motion out; the solid sub-steps within the
// coupler's step, saves and restores its state for iterative schemes and checkpoints through the
// part (state for restart bitwise).
#include "coupling/interface.hpp"
#include "solid_tlsph/solid.hpp"

namespace fsi::app::tlsph_plugin {

/// Model: TlsphModel or TlsphModel3 (solid(), advance, write_state, read_state).
template <int D, class Model> class TlsphAdapter final : public coupling::BasicStructureSolver<D> {
public:
  explicit TlsphAdapter(Model& model) : model_(model) {}
  TlsphAdapter(const TlsphAdapter&) = delete; // bound to its model: the model is not copied
  TlsphAdapter& operator=(const TlsphAdapter&) = delete;
  void initialize() override {}
  void set_interface_loads(const coupling::BasicInterfaceLoads<D>& loads) override {
    model_.solid().set_interface_loads(loads.f);
  }
  void advance(double t, double dt) override { model_.advance(t, dt); }
  coupling::BasicInterfaceMotion<D> interface_motion() const override {
    const auto& s = model_.solid();
    return {s.interface_positions(), s.interface_velocities(), s.interface_accelerations()};
  }
  void save_state() override { saved_ = model_.solid().save(); }
  void restore_state() override { model_.solid().restore(saved_); }
  void write_state(StateArchive& archive) const override { model_.write_state(archive); }
  void read_state(const StateArchive& archive) override { model_.read_state(archive); }

private:
  Model& model_;
  tlsph::TlsphState saved_;
};

} // namespace fsi::app::tlsph_plugin
