#pragma once
// What every particle fluid's plug-in reads and does alike: the regions filled with particles, the
// domain box, the filling, and the memory footprint of the particles.
#include "fsi_app/ranks.hpp"
#include "fsi_app/solver_plugin.hpp"
#include "particles/lattice.hpp"
#include "particles/setup_block.hpp"

#include <optional>
#include <span>

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

/// A box block of a 3-D particle fluid (a region, its tank, its domain): {min: [x, y, z], max: [x,
/// y, z]}, max above min on every axis.
struct BoxRegion {
  Vec3 min = Vec3::Zero(), max = Vec3::Zero();
  int line = 0;
};

/// Reads a box block (`what` names it in the key docs); s.fail for a missing corner or max not
/// above min.
BoxRegion read_box_region(Section& s, const std::string& what);

/// Reads a 3-D particle fluid's `regions` (boxes, at least one unless `other_regions`: the fluid
/// has regions of another kind, none thinner than the spacing l0) and its optional `domain` box.
void read_box_area(Section& s, double l0, std::vector<BoxRegion>& regions,
                   std::optional<BoxRegion>& domain, bool other_regions = false);

/// The key periodic_z of a 3-D particle fluid (documented in 2-D too): the fluid and its box tank
/// wrap along z over the tank's depth.
bool read_periodic_z(Section& s);
/// periodic_z's conditions (s.fail): a box `tank` whose depth is a whole number of `l0`, a
/// `domain` (if given) of the tank's z range.
void check_periodic_z(Section& s, const std::optional<BoxRegion>& tank,
                      const std::optional<BoxRegion>& domain, double l0);
/// The refusal of a periodic fluid under mpirun, naming `key` (the cause of the wrap).
std::string periodic_refusal(const Section& s, const std::string& key);

/// Whether p lies in the box [lo, hi], its faces included.
bool inside_box(const Vec3& p, const Vec3& lo, const Vec3& hi);

/// Calls visit(p) for each box region's cell-centred lattice point at spacing l0
/// (particles::for_each_lattice_point, l0/2 from its faces), region after region, a point inside
/// an earlier region left out: the fill's points in id order, without a list.
template <class Visit>
void for_each_box_region_point(const std::vector<BoxRegion>& regions, double l0, Visit visit) {
  for (std::size_t i = 0; i < regions.size(); ++i)
    particles::for_each_lattice_point<3>(regions[i].min, regions[i].max, l0, [&](const Vec3& p) {
      for (std::size_t j = 0; j < i; ++j)
        if (inside_box(p, regions[j].min, regions[j].max)) return;
      visit(p);
    });
}

/// A process's part of a 3-D fluid's fill: ids [ids.first, ids.last) of the whole fill of
/// `total` (the ids one process gives them), their positions `x`.
struct Fill3 {
  std::vector<Vec3> x;
  particles::BlockRange ids;
  std::size_t total = 0;
};

/// The ids of this process's part of a fill of n: its block under mpirun (`ranks` decomposed,
/// particles::block_of), else all n.
particles::BlockRange fill_block(std::size_t n, const Ranks& ranks);

/// The box regions' fill less the points `keep` refuses, numbered in its order, then `after`
/// more points (ids from the boxes' count, total - after, which the caller appends for its
/// part): this process's part (fill_block) of the boxes' points, built without the others (a
/// first pass counts, a second keeps; `keep` is called twice a point).
template <class Keep>
Fill3 fill_box_part(const std::vector<BoxRegion>& regions, double l0, const Ranks& ranks, Keep keep,
                    std::size_t after = 0) {
  std::size_t n = 0;
  for_each_box_region_point(regions, l0, [&](const Vec3& p) { n += keep(p) ? 1 : 0; });
  Fill3 fill;
  fill.total = n + after;
  fill.ids = fill_block(fill.total, ranks);
  fill.x.reserve(fill.ids.size());
  std::size_t id = 0;
  for_each_box_region_point(regions, l0, [&](const Vec3& p) {
    if (!keep(p)) return;
    if (id >= fill.ids.first && id < fill.ids.last) fill.x.push_back(p);
    ++id;
  });
  return fill;
}

/// A 3-D particle fluid's domain: `domain` as given, else the box around the tank, `tank_points`
/// (an STL tank's, a surface region's) and the regions, grown by margin on every side.
std::pair<Vec3, Vec3> box_domain(const std::optional<BoxRegion>& domain,
                                 const std::optional<BoxRegion>& tank,
                                 std::span<const Vec3> tank_points,
                                 const std::vector<BoxRegion>& regions, double margin);

/// The box regions lie in the domain and in the tank (when given), and every fluid probe's point
/// (a probe without a structure) in the domain: s.fail names fluid.domain or fluid.regions, the
/// probe's section its point.
void check_box_regions(const Scene& scene, Section& s, std::vector<Section>& probes,
                       const std::vector<BoxRegion>& regions, const std::optional<BoxRegion>& tank,
                       const Vec3& domain_min, const Vec3& domain_max);

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
