#pragma once
// The SPH fluid of a 3-D scene (dimension: 3, fluid.type: sph): boxes of water in an open box
// tank (fluid.tank, its dummies by sph::box_walls, y up), not coupled to structures (a 3-D
// interface boundary is not yet written; the scene reader refuses structures beside a 3-D fluid).
#include "fluid_sph/sph_fluid.hpp"
#include "fsi_app/solver_plugin.hpp"
#include "sph/sph_spec.hpp"

#include <memory>

namespace fsi::app::sph_plugin {

/// The solver options of a 3-D scene's fluid block; without a domain, the box around the tank
/// and the regions with a margin of 8 l0 (the tank's 4 dummy layers and a kernel support).
sph::SphOptions3 sph_options3(const Scene& scene);

/// The plug-in's functions for a 3-D scene (sph_plugin.cpp picks them by scene.dimension).
void check3(const Scene& scene, Section& s, std::vector<Section>& probes);
Footprint footprint3(const Scene& scene);
/// The options, and that the regions hold particles (InputError naming the fluid block).
void validate3(const Scene& scene);

class SphModel3 final : public FluidPart {
public:
  /// Fills the regions (each from its lowest corner, l0/2 from its faces; a point inside an
  /// earlier region is left out) and builds the tank's dummies.
  explicit SphModel3(const Scene& scene);
  ~SphModel3() override;
  void advance(double time, double dt) override;
  /// The fluid's advection step Dt (its dual criteria; the Courant number is not used).
  std::optional<double> stable_dt(double courant) const override;
  void write_frame(FieldsFile& file, const std::vector<std::string>& fields) const override;
  std::optional<double> probe(const ProbeSpec& probe) const override;
  std::optional<ParticleCount> particle_count() const override;
  void report(JsonObject& run) const override;
  void write_state(StateArchive& archive) const override;
  void read_state(const StateArchive& archive) override;
  /// Throws RunError: a 3-D fluid is not coupled.
  coupling::FluidSolver& coupling_solver() override;

  const sph::SphFluid3& fluid() const { return *fluid_; }

private:
  std::unique_ptr<sph::SphFluid3> fluid_;
  std::size_t initial_count_ = 0;
  mutable std::vector<double> xyz_, v_; // output buffers
};

/// The fluid particles of a 3-D scene's regions (SphModel3's fill).
std::vector<Vec3> fill_regions3(const SphSpec3& f);

} // namespace fsi::app::sph_plugin
