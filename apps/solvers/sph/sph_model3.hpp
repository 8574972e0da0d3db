#pragma once
// The SPH fluid of a 3-D scene (dimension: 3, fluid.type: sph): boxes of water in an open box
// tank (fluid.tank, its dummies by sph::box_walls, y up) and, coupled, on boundary points of each
// structure's interface mesh (fluid_sph/interface_boundary3.hpp), whose forces return to the
// interface nodes (BoundaryAdapter<3>). Where a structure's boundary points stand, the tank's
// dummies are left out (e.g. a plate forming the tank's floor: the fluid sees the plate there,
// not a rigid floor); no fluid particle is filled behind an interface or within l0/2 of it.
#include "decomposed_particles.hpp"
#include "fluid_sph/interface_boundary3.hpp"
#include "fluid_sph/sph_fluid.hpp"
#include "fsi_app/solver_plugin.hpp"
#include "sph/sph_spec.hpp"

#include <memory>

namespace fsi::app::sph_plugin {

template <int D> class BoundaryAdapter;

/// The solver options of a 3-D scene's fluid block; without a domain, the box around the tank
/// and the regions with a margin of 8 l0 (the tank's 4 dummy layers and a kernel support).
sph::SphOptions3 sph_options3(const Scene& scene);

/// The plug-in's functions for a 3-D scene (sph_plugin.cpp picks them by scene.dimension).
void check3(const Scene& scene, Section& s, std::vector<Section>& probes);
Footprint footprint3(const Scene& scene);
/// The options, the interfaces' boundary points and that the regions hold particles (InputError
/// naming the fluid block).
void validate3(const Scene& scene, const std::vector<InterfaceMesh3>& interfaces = {});

class SphModel3 final : public FluidPart {
public:
  /// Fills the regions (each from its lowest corner, l0/2 from its faces; a point inside an
  /// earlier region, behind an interface or within l0/2 of it is left out), builds the tank's
  /// dummies (less those in a dp cell of the tank's lattice that holds a boundary point) and the
  /// interfaces' boundary points (4 layers at spacing l0).
  /// Under mpirun (`ranks` decomposed) each rank builds its block of the fill only
  /// (DecomposedParticles::setup); decompose() starts the fluid's first advection step.
  explicit SphModel3(const Scene& scene, const std::vector<InterfaceMesh3>& interfaces = {},
                     const Ranks& ranks = OneProcess());
  ~SphModel3() override;
  void advance(double time, double dt) override;
  /// The fluid's advection step Dt (its dual criteria; the Courant number is not used).
  std::optional<double> stable_dt(double courant) const override;
  void write_frame(FieldsFile& file, const std::vector<std::string>& fields) const override;
  /// Decomposed: the value gather_frame evaluated over every rank.
  std::optional<double> probe(const ProbeSpec& probe) const override;
  std::optional<ParticleCount> particle_count() const override;
  void report(JsonObject& run) const override;
  /// The fluid steps over `ranks` (parallel::ParticleDecomposition under mpirun); every rank
  /// built it from the whole scene and holds every wall particle, the boundary points moved
  /// alike on every rank by the same (rank 0's) interface motion.
  bool decompose(const Ranks& ranks) override;
  /// Decomposed: every rank's owned particles to rank 0 in id order (one-process files and
  /// N-process files compare directly) and every probe evaluated over every rank.
  void gather_frame() override;
  /// The fluid under "fluid/" and, coupled, the interface motion at the fluid's time under
  /// "fluid/interface/motion"; collective when decomposed (the one-process format, rank 0's).
  void write_state(StateArchive& archive) const override;
  void read_state(const StateArchive& archive) override;
  /// Throws RunError: a 3-D fluid couples through coupling_solver3().
  coupling::FluidSolver& coupling_solver() override;
  /// F against the interfaces the model was built with (BoundaryAdapter<3>).
  coupling::FluidSolver3& coupling_solver3() override;

  const sph::SphFluid3& fluid() const { return *fluid_; }
  /// Boundary points of each coupled interface, in order; they are the fluid's wall particles
  /// from first_point() on.
  const std::vector<sph::InterfaceBoundary3>& boundaries() const { return boundaries_; }
  std::size_t first_point() const { return first_point_; }

private:
  /// The probe's value (collective when decomposed).
  std::optional<double> evaluate(const ProbeSpec& probe) const;

  std::vector<sph::InterfaceBoundary3> boundaries_;
  std::vector<std::vector<Vec3>> interface_x_; // each interface's nodes where its points are now
  DecomposedParticles<3> ranks_;               // the hook, before the fluid that uses it
  std::vector<ProbeSpec> probes_; // the scene's, evaluated by gather_frame when decomposed
  std::unique_ptr<sph::SphFluid3> fluid_;
  std::unique_ptr<BoundaryAdapter<3>> adapter_;
  std::size_t first_point_ = 0;
  mutable std::vector<double> xyz_, v_; // output buffers
};

} // namespace fsi::app::sph_plugin
