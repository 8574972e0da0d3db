#pragma once
// The EMPS fluid of a 3-D scene (dimension: 3, fluid.type: emps): boxes of water in a tank of
// static ERP triangles (fluid.tank, a closed box, or fluid.tank_file, an STL surface), not
// coupled to structures (the scene reader refuses structures beside a 3-D fluid).
#include "emps/emps_spec.hpp"
#include "fluid_emps/emps_fluid.hpp"
#include "fsi_app/solver_plugin.hpp"
#include "geometry_erp/triangle_locator.hpp"
#include "geometry_erp/triangle_wall_set.hpp"

#include <memory>

namespace fsi::app::emps_plugin {

/// The solver options of a 3-D scene's fluid block; without a domain, the box around the tank
/// and the regions with a margin of 4 r_e.
emps::FluidOptions3 fluid_options3(const Scene& scene);

/// The plug-in's functions for a 3-D scene (emps_plugin.cpp picks them by scene.dimension).
void check3(const Scene& scene, Section& s, std::vector<Section>& probes);
Footprint footprint3(const Scene& scene);
/// The regions hold particles, each on the fluid side of its nearest tank triangle (an STL
/// surface facing away from the fluid is refused naming its file); InputError naming the block.
void validate3(const Scene& scene);

class EmpsModel3 final : public FluidPart {
public:
  /// Builds the tank's triangles and fills the regions (each from its lowest corner, l0/2 from
  /// its faces; a point inside an earlier region is left out).
  explicit EmpsModel3(const Scene& scene);
  void advance(double time, double dt) override;
  std::optional<double> stable_dt(double courant) const override;
  /// particles: the count; wall_gap: the smallest distance of a particle centre to its nearest
  /// triangle within r_e (negative behind it; +inf with none near), m; the 2-D probes' others.
  std::optional<double> probe(const ProbeSpec& probe) const override;
  /// The grid "particles" (3-D points): velocity, pressure, pnd, free_surface.
  void write_frame(FieldsFile& file, const std::vector<std::string>& fields) const override;
  std::optional<ParticleCount> particle_count() const override;
  void report(JsonObject& run) const override;
  void write_state(StateArchive& archive) const override;
  void read_state(const StateArchive& archive) override;
  /// Throws RunError: a 3-D fluid is not coupled.
  coupling::FluidSolver& coupling_solver() override;

  const emps::EmpsFluid3& fluid() const { return *fluid_; }
  const erp::TriangleWallSet& walls() const { return *walls_; }

private:
  std::unique_ptr<erp::TriangleWallSet> walls_; // before the fluid that keeps a reference
  std::unique_ptr<emps::EmpsFluid3> fluid_;
  std::unique_ptr<erp::TriangleLocator> locator_; ///< the wall_gap probe's nearest triangles
  mutable erp::TriangleHits hits_;
  std::size_t initial_count_ = 0;
  mutable std::vector<double> xyz_, v_, flag_; // output buffers
};

/// The fluid particles of a 3-D scene's regions (EmpsModel3's fill).
std::vector<Vec3> fill_regions3(const FluidSpec3& f);
/// The tank's triangles: the box's 12, or the STL surface's.
std::unique_ptr<erp::TriangleWallSet> tank_walls(const FluidSpec3& f);

} // namespace fsi::app::emps_plugin
