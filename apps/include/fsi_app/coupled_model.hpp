#pragma once
// A fluid and the scene's structures coupled through the scene's coupling scheme (css, bgs, ...),
// or one side alone against a recorded interface.h5 (a scheme that replays a motion: the fluid
// against it, the structures not solved; one that replays loads: the structures under them, the
// fluid not solved). The part not solved stays at its initial state in fields and probes. It
// knows the solvers only through their plug-in interfaces (solver_plugin.hpp); the structures'
// interfaces are concatenated in scene order (coupling::StructureGroup). BasicCoupledModel<D> for
// D = 2 (CoupledModel) and 3 (CoupledModel3: the plug-ins' build3, interface_mesh3 and
// coupling_solver3; interface.h5 with 3 components per node and the faces, recorded and replayed
// as in 2-D).
#include "coupling/registry.hpp"
#include "coupling/scheme.hpp"
#include "coupling/structure_group.hpp"
#include "fsi_app/root_structures.hpp"
#include "fsi_app/solver_plugin.hpp"

#include <array>
#include <fstream>
#include <memory>

namespace fsi::app {

template <int D> class BasicInterfaceHistory;
template <int D> class BasicInterfaceHistoryWriter;

/// The recorded interface the scene's one-way scheme replays (coupling.motion or .loads), or
/// nullptr for a scheme that replays none. InputError (`FILE:LINE: coupling.motion|loads: what`)
/// for a recording whose node count differs from the `nodes` of the scene's interfaces.
template <int D>
std::unique_ptr<BasicInterfaceHistory<D>> open_replay(const Scene& scene, std::size_t nodes);

template <int D> class BasicCoupledModel final : public Model {
public:
  using Scheme = coupling::BasicCouplingScheme<D>;
  /// Throws InputError (scene file and line) for coupling options the scheme rejects.
  /// one_way_*: InputError (`FILE:LINE: coupling.motion|loads: what`) for a recorded file whose
  /// node count differs from the interface's. `ranks`: the fluid's (FluidPlugin::build).
  explicit BasicCoupledModel(const Scene& scene, const Ranks& ranks = OneProcess());
  ~BasicCoupledModel() override;
  void advance(double time, double dt) override;
  /// The smallest of the fluid's and the structures' stable steps for the Courant number
  /// (time.courant): the coupling step follows the fluid's step.
  std::optional<double> stable_dt(double courant) const override;
  /// DIR/coupling.csv: one row per coupling step (iterations, residuals of eq. 68, relaxation,
  /// convergence, wall times, the fluid's force: 2-D its force_parts fx_, fy_; 3-D the loads'
  /// sum fx_total, fy_total, fz_total, N, to 17 digits), flushed every 1000 rows and at the end.
  /// With coupling.record_interface also DIR/interface.h5 (row 0 at t = 0, then one row per
  /// step; not continued across a restart: refused with InputError).
  void open_logs(const std::filesystem::path& out, bool resume) override;
  void flush_logs() override;
  void declare(FieldsFile& file) const override;
  void write_frame(FieldsFile& file, const std::vector<std::string>& fields) const override;
  std::optional<double> probe(const ProbeSpec& probe) const override;
  void report(JsonObject& run) const override;
  std::vector<std::string> take_notes() override;
  std::optional<ParticleCount> particle_count() const override { return fluid_->particle_count(); }
  /// Decomposed: collective (rank 0's structures' finiteness broadcast).
  std::optional<std::string> non_finite() const override;
  /// The coupler with both participants (coupling::CouplingScheme::write_state).
  void write_state(StateArchive& archive) const override { scheme_->write_state(archive); }
  void read_state(const StateArchive& archive) override { scheme_->read_state(archive); }
  /// Under mpirun (issue 47): the fluid decomposed, the structures solved on rank 0
  /// (RootStructures), the loads every rank's summed; every rank runs the same scheme on the
  /// same data. False when the fluid cannot be decomposed.
  bool decompose(const Ranks& ranks) override;
  void gather_frame() override;

  const Scheme& scheme() const { return *scheme_; }
  FluidPart& fluid() { return *fluid_; }
  StructurePart& structure(std::size_t i) { return *structures_[i]; }

private:
  void write_forces(std::ostream& log) const; ///< the force columns of coupling.csv's row
  /// 2-D: the fluid's force_parts (decomposed: every rank's summed after each fluid advance).
  std::vector<std::pair<std::string, Vec2>> force_parts() const {
    return ranks_ ? forces_ : fluid_->force_parts();
  }
  std::vector<std::unique_ptr<StructurePart>> structures_;
  std::unique_ptr<FluidPart> fluid_;
  std::unique_ptr<coupling::BasicStructureGroup<D>> group_;
  std::unique_ptr<RootStructures<D>> root_; ///< the group as the scheme's S
  const Ranks* ranks_ = nullptr;            ///< set when decomposed
  std::vector<std::pair<std::string, Vec2>> forces_;
  std::unique_ptr<Scheme> scheme_;
  std::unique_ptr<std::ofstream> step_log_;
  // Recording and one-way replay.
  class FluidTap;
  std::unique_ptr<FluidTap> tap_; ///< the fluid adapter, remembering the motion it was given
  std::unique_ptr<BasicInterfaceHistory<D>> replay_;
  std::unique_ptr<BasicInterfaceHistoryWriter<D>> history_;
  std::vector<std::array<std::size_t, 6>> faces_; ///< 3-D: the interfaces' faces, group numbering
  bool record_ = false;
  coupling::SchemeNeeds needs_; ///< what the scheme couples (the registry's declaration)
};

extern template class BasicCoupledModel<2>;
extern template class BasicCoupledModel<3>;
using CoupledModel = BasicCoupledModel<2>;
using CoupledModel3 = BasicCoupledModel<3>;

} // namespace fsi::app
