#pragma once
// The SPH fluid of a scene (fluid.type: sph) on the scene's walls (dummy particles, static or
// with the walls' prescribed motion) and, coupled, on boundary points of each structure's
// interface mesh (fluid_sph/interface_boundary.hpp), whose forces return to the interface nodes
// (BoundaryAdapter<2>).
#include "decomposed_particles.hpp"
#include "fluid_sph/interface_boundary.hpp"
#include "fluid_sph/sph_fluid.hpp"
#include "fsi_app/solver_plugin.hpp"
#include "sph/sph_spec.hpp"

#include <memory>

namespace fsi::app::sph_plugin {

template <int D> class BoundaryAdapter;

/// The solver options of the scene's fluid block; without a domain, the box around walls and
/// regions with a margin of 8 l0 (the walls' 4 dummy layers and a kernel support).
sph::SphOptions sph_options(const Scene& scene);

class SphModel final : public FluidPart {
public:
  /// Fills the regions (l0/2 from walls and edges, the structures' areas `solid` kept free),
  /// builds the wall dummies and the interfaces' boundary points. Throws InputError (scene file
  /// and line) for options or regions the fluid refuses. Under mpirun (`ranks` decomposed) each
  /// rank builds its block of the fill only (DecomposedParticles::setup); decompose() starts the
  /// fluid's first advection step.
  SphModel(const Scene& scene, const std::vector<InterfaceMesh>& interfaces = {},
           const std::vector<Polygon>& solid = {}, const Ranks& ranks = OneProcess());
  ~SphModel() override;
  /// Acoustic steps of the fluid's own criteria up to time + dt (the last one shortened).
  void advance(double time, double dt) override;
  /// The fluid's advection step Dt (its dual criteria; the Courant number is not used): the
  /// run's step holds the acoustic steps that cross it.
  std::optional<double> stable_dt(double courant) const override;
  void write_frame(FieldsFile& file, const std::vector<std::string>& fields) const override;
  /// Decomposed: the value gather_frame evaluated over every rank.
  std::optional<double> probe(const ProbeSpec& probe) const override;
  std::optional<ParticleCount> particle_count() const override;
  std::optional<std::string> non_finite() const override;
  void report(JsonObject& run) const override;
  /// The fluid steps over `ranks` (parallel::ParticleDecomposition under mpirun); every rank
  /// built its block of the fill and holds every wall particle, the boundary points moved
  /// alike on every rank by the same (rank 0's) interface motion.
  bool decompose(const Ranks& ranks) override;
  /// Decomposed: every rank's owned particles to rank 0 in id order (one-process files and
  /// N-process files compare directly) and every probe evaluated over every rank.
  void gather_frame() override;
  /// The fluid under "fluid/", the interface motion at the fluid's time under "fluid/interface/";
  /// collective when decomposed (the one-process format, written by rank 0).
  void write_state(StateArchive& archive) const override;
  void read_state(const StateArchive& archive) override;
  coupling::FluidSolver& coupling_solver() override;
  /// The fluid's force on the coupled structures (on all walls without one), N/m.
  std::vector<std::pair<std::string, Vec2>> force_parts() const override;

  sph::SphFluid& fluid() { return *fluid_; }
  const sph::SphFluid& fluid() const { return *fluid_; }
  /// Boundary points of each coupled interface, in order.
  const std::vector<sph::InterfaceBoundary>& boundaries() const { return boundaries_; }
  /// Mean force of the fluid on the coupled structures (on all walls without one) over the last
  /// advance, N/m; decomposed, every rank's particles' summed (collective).
  Vec2 wall_force() const;

private:
  /// The probe's value (collective when decomposed).
  std::optional<double> evaluate(const ProbeSpec& probe) const;

  std::vector<sph::InterfaceBoundary> boundaries_;
  std::vector<std::vector<Vec2>> interface_x_; // each interface's nodes where its points are now
  DecomposedParticles<2> ranks_;               // the hook, before the fluid that uses it
  std::vector<ProbeSpec> probes_; // the scene's, evaluated by gather_frame when decomposed
  std::unique_ptr<sph::SphFluid> fluid_;
  std::unique_ptr<BoundaryAdapter<2>> adapter_;
  std::size_t first_point_ = 0;
  bool tracked_ = false, interface_acceleration_ = false;
  Vec2 wall_force_ = Vec2::Zero();     // uncoupled: the walls' mean force over the last advance
  mutable std::vector<double> xy_, v_; // output buffers
};

} // namespace fsi::app::sph_plugin
