#pragma once
// The EMPS fluid of a 3-D scene (dimension: 3, fluid.type: emps): boxes of water in a tank of
// ERP triangles (fluid.tank, a closed box, or fluid.tank_file, an STL surface; static, or moved
// rigidly by fluid.tank_motion to t + dt before each step) and,
// coupled, the flat triangles of each structure's interface (erp::InterfaceTriangles, group
// 1 + j), moved by the coupler through TriangleAdapter. A tank triangle the interfaces' faces
// cover wholly is left out (a plate forming the tank's floor: the fluid sees the plate there);
// a partial cover is refused (tank_cover.hpp).
#include "emps/emps_spec.hpp"
#include "emps/frame_particles.hpp"
#include "emps/triangle_adapter.hpp"
#include "emps/wall_point_pressure.hpp"
#include "fluid_emps/emps_fluid.hpp"
#include "fsi_app/solver_plugin.hpp"
#include "geometry_erp/motion3.hpp"
#include "geometry_erp/triangle_locator.hpp"
#include "geometry_erp/triangle_wall_set.hpp"

#include <memory>
#include <optional>

namespace fsi::app::emps_plugin {

/// The solver options of a 3-D scene's fluid block; without a domain, the box around the tank
/// and the regions with a margin of 4 r_e.
emps::FluidOptions3 fluid_options3(const Scene& scene);

/// The plug-in's functions for a 3-D scene (emps_plugin.cpp picks them by scene.dimension).
void check3(const Scene& scene, Section& s, std::vector<Section>& probes);
Footprint footprint3(const Scene& scene);
/// The fill of the scene's regions (box regions, then region_file's points outside every box):
/// the whole on one process; under mpirun (`ranks` decomposed) this rank's block of ids
/// (particles::block_of), the box regions' lattices enumerated without keeping the rest
/// (region_file's points are still built whole, then cut).
Fill3 fill_regions3(const FluidSpec3& f, const Ranks& ranks);

/// The regions hold particles (`fill`, fill_regions3's), each on the fluid side of its nearest
/// wall triangle (an STL surface facing away from the fluid is refused naming its file; a moving
/// tank at t = 0; its motion's table covers the run and there are no structures), the
/// interfaces' meshes make triangles and cover tank triangles wholly or not at all; InputError
/// naming the key. Under mpirun (`ranks` decomposed) each rank checks its block of the fill
/// only, and every rank throws the message of the first particle behind a wall in id order, as
/// one process does (collective).
void validate3(const Scene& scene, const std::vector<InterfaceMesh3>& interfaces, const Fill3& fill,
               const Ranks& ranks);
/// validate3 on one process, over the whole fill (fsi check, the plug-in's validate).
void validate3(const Scene& scene, const std::vector<InterfaceMesh3>& interfaces = {});

class EmpsModel3 final : public FluidPart {
public:
  /// Builds the tank's triangles (less those the interfaces cover), the interfaces' triangles at
  /// their reference positions, and fills the regions (each from its lowest corner, l0/2 from
  /// its faces; a point inside an earlier region is left out).
  /// Under mpirun (`ranks` decomposed) each rank builds its block of the fill only
  /// (DecomposedParticles::setup); decompose() starts the fluid.
  explicit EmpsModel3(const Scene& scene, const std::vector<InterfaceMesh3>& interfaces = {},
                      const Ranks& ranks = OneProcess());
  void advance(double time, double dt) override;
  std::optional<double> stable_dt(double courant) const override;
  /// particles: the count; wall_gap: the smallest distance of a particle centre to its nearest
  /// triangle within r_e (negative behind it; +inf with none near), m; water_height: a wave
  /// gauge, the top (centre + l0/2 against gravity) of the highest bulk particle (pnd >= n0/2)
  /// within l0 of the vertical through the point, above the point, m (0: none; the bulk's
  /// threshold is the probe's pnd_fraction); wall_pressure: WallPointPressure's p at the
  /// probe's point, Pa; the 2-D probes' others.
  std::optional<double> probe(const ProbeSpec& probe) const override;
  /// The grid "particles" (3-D points): velocity, pressure, pnd, free_surface.
  void write_frame(FieldsFile& file, const std::vector<std::string>& fields) const override;
  std::optional<ParticleCount> particle_count() const override;
  void report(JsonObject& run) const override;
  void write_state(StateArchive& archive) const override;
  void read_state(const StateArchive& archive) override;
  /// Throws RunError: a 3-D fluid couples through coupling_solver3().
  coupling::FluidSolver& coupling_solver() override;
  /// F against the interfaces the model was built with (TriangleAdapter).
  coupling::FluidSolver3& coupling_solver3() override { return *adapter_; }
  /// The fluid steps over `ranks` (parallel::ParticleDecomposition<3> under mpirun); every rank
  /// built its block of the fill and holds every wall triangle (the ghosts' wall hits are
  /// computed locally). Without structures (the adapter's state is this rank's).
  bool decompose(const Ranks& ranks) override;
  /// Decomposed: every rank's owned particles in id order (to rank 0, or each rank's own when
  /// fields.h5 is written collectively, the probes then evaluated over every rank), and the
  /// kinetic energy (a global sum) for the probes.
  void gather_frame() override;

  const emps::EmpsFluid3& fluid() const { return *fluid_; }
  const erp::TriangleWallSet& walls() const { return *walls_; }
  /// The triangles of each coupled interface, in order; the tank's come first.
  const std::vector<erp::InterfaceTriangles>& interface_triangles() const { return interfaces_; }

private:
  /// The particles a frame and the probes read: the fluid's own, or (decomposed) the gathered.
  FrameParticles<3> frame() const {
    return gathered_.view(ranks_, fluid_->particles(), fluid_->owned());
  }
  /// The probe over frame(); collective when each rank holds its own rows (ranks_.rows()).
  std::optional<double> evaluate(const ProbeSpec& probe) const;

  std::unique_ptr<erp::TriangleWallSet> walls_; // before the fluid that keeps a reference
  std::vector<erp::InterfaceTriangles> interfaces_;
  std::optional<erp::RigidTriangles3> tank_motion_; ///< fluid.tank_motion over the tank's nodes
  DecomposedParticles<3> ranks_;                    // the hook, before the fluid that uses it
  std::unique_ptr<emps::EmpsFluid3> fluid_;
  std::unique_ptr<TriangleAdapter> adapter_;
  std::unique_ptr<erp::TriangleLocator> locator_; ///< the wall_gap probe's nearest triangles
  mutable erp::TriangleHits hits_;
  std::vector<ProbeSpec> probes_; // the scene's, evaluated by gather_frame on every rank's rows
  mutable std::vector<double> xyz_, v_, flag_;   // output buffers
  GatheredParticles<3> gathered_;                // on rank 0, in id order
  double kinetic_energy_ = 0.0;                  // decomposed: at the last gather, J
  std::unique_ptr<WallPointProbes> wall_points_; // the scene's wall_pressure probes
};

/// fluid.tank_motion over every node of `walls` (a moving tank has no structures: validate3).
std::optional<erp::RigidTriangles3> tank_motion(const FluidSpec3& f,
                                                const erp::TriangleWallSet& walls);
/// The fluid's walls: the tank's triangles (the box's 12, or the STL surface's) less those the
/// interfaces cover wholly (group 0), then each interface's triangles (group 1 + j) into
/// `triangles`; InputError naming the scene's key (a partial cover, a bad interface mesh).
std::unique_ptr<erp::TriangleWallSet> fluid_walls(const Scene& scene,
                                                  const std::vector<InterfaceMesh3>& interfaces,
                                                  std::vector<erp::InterfaceTriangles>& triangles);

} // namespace fsi::app::emps_plugin
