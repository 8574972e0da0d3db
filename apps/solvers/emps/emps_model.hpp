#pragma once
// The EMPS fluid of a scene (fluid.type: emps) against its polygon walls (static or with
// prescribed motion) and the interfaces of the structures it is coupled to.
#include "emps/emps_adapter.hpp"
#include "emps/emps_spec.hpp"
#include "emps/frame_particles.hpp"
#include "fluid_emps/emps_fluid.hpp"
#include "fsi/core/interface_mesh.hpp"
#include "fsi_app/fluid_regions.hpp"
#include "fsi_app/solver_plugin.hpp"
#include "geometry_erp/interface_walls.hpp"
#include "geometry_erp/wall_set.hpp"

#include <memory>

namespace fsi::app::emps_plugin {

/// The solver options of the scene's fluid block; without a domain, the box around walls and
/// regions with a margin of 4 r_e.
emps::FluidOptions fluid_options(const Scene& scene);

class EmpsModel final : public FluidPart {
public:
  /// Builds walls, fills the regions with particles and maps the options. Each coupled
  /// structure's interface (as the structure describes it) becomes ERP walls whose nodes are its
  /// interface nodes (eqs. 47-51), and the areas the structures occupy (`solid`) are kept free of
  /// particles. Throws InputError (scene file and line) for a motion table or region that does
  /// not fit. Under mpirun (`ranks` decomposed) each rank builds its block of the fill only
  /// (DecomposedParticles::setup); decompose() starts the fluid.
  EmpsModel(const Scene& scene, const std::vector<InterfaceMesh>& interfaces = {},
            const std::vector<Polygon>& solid = {}, const Ranks& ranks = OneProcess());
  void advance(double time, double dt) override;
  std::optional<double> stable_dt(double courant) const override;
  void declare(FieldsFile& file) const override;
  void write_frame(FieldsFile& file, const std::vector<std::string>& fields) const override;
  std::optional<double> probe(const ProbeSpec& probe) const override;
  std::optional<ParticleCount> particle_count() const override;
  std::optional<std::string> non_finite() const override;
  void report(JsonObject& run) const override;
  /// The fluid under "fluid/", all wall nodes under "walls/".
  void write_state(StateArchive& archive) const override;
  void read_state(const StateArchive& archive) override;
  coupling::FluidSolver& coupling_solver() override { return *adapter_; }
  /// Pressure (mirror, eqs. 25-26), repulsive (eq. 27 and the wall damper) and viscous (eq. 24)
  /// parts of the wall force on the interfaces' segments (eq. 52, with the sign on the structure).
  /// Decomposed: collective, every rank's particles summed.
  std::vector<std::pair<std::string, Vec2>> force_parts() const override;
  /// The fluid steps over `ranks` (parallel::ParticleDecomposition under mpirun); every rank
  /// built its block of the fill (or read the whole checkpoint).
  bool decompose(const Ranks& ranks) override;
  /// Decomposed: every rank's owned particles in id order (to rank 0, or each rank's own when
  /// fields.h5 is written collectively, the probes then evaluated over every rank; one-process
  /// files and N-process files compare directly), the kinetic energy and the wall force (global
  /// sums) for the probes.
  void gather_frame() override;

  emps::EmpsFluid& fluid() { return *fluid_; }
  erp::WallSet& walls() { return *walls_; }
  /// The walls of the coupled structures' interfaces, in the order given.
  const std::vector<erp::InterfaceWalls>& interface_walls() const { return interface_walls_; }
  const FluidAdapter& adapter() const { return *adapter_; }

private:
  /// The particles a frame and the probes read: the fluid's own, or (decomposed) the gathered.
  FrameParticles<2> frame() const {
    return gathered_.view(ranks_, fluid_->particles(), fluid_->owned());
  }
  /// The probe over frame(); collective when each rank holds its own rows (ranks_.rows()).
  std::optional<double> evaluate(const ProbeSpec& probe) const;
  /// The force on the interfaces' segments (every wall's without one); decomposed: collective,
  /// every rank's particles summed.
  emps::WallForceParts wall_force() const;
  /// [first, last) wall segments of the interfaces (every wall without one).
  std::pair<int, int> interface_segments() const;

  std::unique_ptr<erp::WallSet> walls_;
  std::vector<erp::InterfaceWalls> interface_walls_;
  DecomposedParticles<2> ranks_; // the hook, before the fluid that uses it
  std::unique_ptr<emps::EmpsFluid> fluid_;
  std::unique_ptr<FluidAdapter> adapter_;
  std::vector<ProbeSpec> probes_; // the scene's, evaluated by gather_frame on every rank's rows
  std::vector<std::string> wall_names_; ///< by wall group: the scene's walls, then the interfaces
  mutable std::vector<double> xy_, v_, flag_; // output buffers
  GatheredParticles<2> gathered_;             // on rank 0, in id order
  double kinetic_energy_ = 0.0;               // decomposed: at the last gather, J/m
  emps::WallForceParts gathered_force_;       // decomposed: wall_force() at the last gather
};

} // namespace fsi::app::emps_plugin
