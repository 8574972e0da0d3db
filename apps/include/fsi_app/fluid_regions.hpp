#pragma once
// What every particle fluid's plug-in reads and does alike: the regions filled with particles, the
// domain box, the filling, and the memory footprint of the particles.
#include "fsi_app/solver_plugin.hpp"

#include <optional>

namespace fsi::app {

/// The `regions` and `domain` keys of a particle fluid's block.
struct ParticleArea {
  std::vector<Polygon> regions;                ///< closed polygons filled with particles
  std::optional<std::pair<Vec2, Vec2>> domain; ///< (min, max) as given

  /// The domain as given; else the box around the scene's walls and the regions, grown by margin.
  std::pair<Vec2, Vec2> domain_or_box(const Scene& scene, double margin) const;
};

/// Reads `regions` (at least one; rectangles or polygons) and the optional `domain`, and checks
/// that the spacing l0 fits every region.
ParticleArea read_particle_area(Section& s, double l0);

/// The regions and every fluid probe's point (or box) lie in `domain` (the particles' box,
/// given or derived): s.fail names fluid.domain (fluid.regions without one) or the probe's key.
void check_in_domain(const Scene& scene, Section& s, std::vector<Section>& probes,
                     const ParticleArea& area, const std::pair<Vec2, Vec2>& domain);

/// Each region on its own lattice at spacing l0, l0/2 from the scene's walls (as written) and
/// outside the `solid` areas. InputError (scene file and line) when no particle fits.
std::vector<Vec2> fill_regions(const Scene& scene, const std::vector<Polygon>& regions, double l0,
                               const std::vector<Polygon>& solid);

/// Shoelace area of a closed polygon (either orientation), m^2.
double polygon_area(const Polygon& p);

/// A particle fluid's memory: area / l0^2 particles of `bytes_per_particle` each, and a cell grid
/// of side `cell` over the domain (`padding` extra cells per direction, `bytes_per_cell` each).
struct ParticleGrid {
  double cell, padding, bytes_per_cell;
};
Footprint particle_footprint(const ParticleArea& area, double l0, double bytes_per_particle,
                             const std::pair<Vec2, Vec2>& domain, const ParticleGrid& grid);

/// Adds to `e.overflows` what exceeds a particle fluid's index types: 32-bit particle ids and
/// neighbour indices for e.count particles, int cell indices for `cells` cells (key "l0").
void check_index_range(Footprint& e, double cells);

} // namespace fsi::app
