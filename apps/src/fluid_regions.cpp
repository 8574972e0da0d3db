#include "fsi_app/fluid_regions.hpp"

#include "fsi/core/format.hpp"
#include "geometry_erp/fill.hpp"
#include "geometry_erp/wall_set.hpp"
#include "particles/lattice.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>

namespace fsi::app {

namespace {

std::vector<Vec2> read_region(Section s) {
  const bool doc = s.context().documenting();
  std::vector<Vec2> polygon;
  if (doc || s.has("polygon")) polygon = s.points("polygon", 3, "closed polygon to fill, m");
  if (doc || !s.has("polygon")) {
    const Vec2 lo = s.vec2("min", "lower-left corner of a rectangle to fill, m");
    const Vec2 hi = s.vec2("max", "upper-right corner, m");
    if (!doc && (hi.x() <= lo.x() || hi.y() <= lo.y()))
      s.fail("max", "must lie above and right of min");
    if (!doc) polygon = {lo, {hi.x(), lo.y()}, hi, {lo.x(), hi.y()}};
  }
  s.finish();
  return polygon;
}

} // namespace

double polygon_area(const Polygon& p) {
  double twice = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec2& a = p[i];
    const Vec2& b = p[(i + 1) % p.size()];
    twice += a.x() * b.y() - b.x() * a.y();
  }
  return 0.5 * std::abs(twice);
}

ParticleArea read_particle_area(Section& s, double l0) {
  const bool doc = s.context().documenting();
  ParticleArea a;
  for (auto& region :
       s.list("regions", "areas filled with particles at spacing l0, each on its own "
                         "lattice from its lower-left corner (l0/2 from its edges)"))
    a.regions.push_back(read_region(region));
  if (!doc && a.regions.empty()) s.fail("regions", "at least one region is required");
  if (auto d = s.block("domain", "particles leaving this box are removed and counted")) {
    const Vec2 lo = d->vec2("min", "lower-left corner, m");
    const Vec2 hi = d->vec2("max", "upper-right corner, m");
    if (!doc && (hi.x() <= lo.x() || hi.y() <= lo.y()))
      d->fail("max", "must lie above and right of min");
    a.domain = {lo, hi};
    d->finish();
  }
  if (doc) return a;
  for (std::size_t i = 0; i < a.regions.size(); ++i) {
    Vec2 lo = a.regions[i][0], hi = a.regions[i][0];
    for (const auto& p : a.regions[i]) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    const Vec2 size = hi - lo;
    if (l0 > size.minCoeff()) {
      std::ostringstream msg;
      msg << "particle spacing " << l0 << " m is larger than fluid region " << i << " (" << size.x()
          << " x " << size.y() << " m)";
      s.fail("l0", msg.str());
    }
  }
  return a;
}

void check_in_domain(const Scene& scene, Section& s, std::vector<Section>& probes,
                     const ParticleArea& area, const std::pair<Vec2, Vec2>& domain) {
  const auto inside = [&](const Vec2& p) {
    return p.x() >= domain.first.x() && p.x() <= domain.second.x() && p.y() >= domain.first.y() &&
           p.y() <= domain.second.y();
  };
  for (std::size_t i = 0; i < area.regions.size(); ++i)
    for (const Vec2& p : area.regions[i])
      if (!inside(p))
        s.fail(area.domain ? "domain" : "regions",
               "fluid region " + std::to_string(i) + " reaches outside the domain");
  // Issue 41: a point outside reads nothing (0) for the whole run.
  for (std::size_t i = 0; i < scene.output.probes.size(); ++i) {
    const ProbeSpec& p = scene.output.probes[i];
    if (!p.structure.empty()) continue;
    if (p.point && !inside(*p.point))
      probes[i].fail("point", "the point is outside the fluid domain");
    if (p.box_min && p.box_max && (!inside(*p.box_min) || !inside(*p.box_max)))
      probes[i].fail("max", "the box reaches outside the fluid domain");
  }
}

std::pair<Vec2, Vec2> ParticleArea::domain_or_box(const Scene& scene, double margin) const {
  if (domain) return *domain;
  Vec2 lo = Vec2::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const auto& w : scene.walls)
    for (const auto& p : w.polyline) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  for (const auto& r : regions)
    for (const auto& p : r) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  return {lo - Vec2(margin, margin), hi + Vec2(margin, margin)};
}

Footprint particle_footprint(const ParticleArea& area, double l0, double bytes_per_particle,
                             const std::pair<Vec2, Vec2>& domain, const ParticleGrid& grid) {
  Footprint e;
  for (const auto& region : area.regions) e.count += polygon_area(region) / (l0 * l0);
  const Vec2 span = domain.second - domain.first;
  const double cells = (std::ceil(span.x() / grid.cell) + grid.padding) *
                       (std::ceil(span.y() / grid.cell) + grid.padding);
  e.bytes = e.count * bytes_per_particle + cells * grid.bytes_per_cell;
  e.key = 4 * cells > e.bytes / 2 && area.domain ? "domain" : "l0";
  e.counts = significant(e.count, 3) + " particles (fluid region area / l0^2) and " +
             significant(cells, 3) + " cells";
  check_index_range(e, cells);
  return e;
}

void check_index_range(Footprint& e, double cells) {
  if (e.count > std::numeric_limits<std::uint32_t>::max())
    e.overflows.emplace_back("l0", significant(e.count, 3) +
                                       " particles: more than the 2^32 particle indices hold");
  if (cells > std::numeric_limits<int>::max())
    e.overflows.emplace_back("l0", significant(cells, 3) +
                                       " cells over the fluid domain: more than 2^31");
}

std::vector<Vec2> fill_regions(const Scene& scene, const std::vector<Polygon>& regions, double l0,
                               const std::vector<Polygon>& solid) {
  std::vector<erp::Polygon> holes = solid;
  std::vector<Vec2> positions;
  // Each region on its own lattice from its lower-left corner, so a region a whole number of l0
  // wide has l0/2 gaps at both sides; earlier regions are holes for later ones (no doubles).
  // Regions and walls are both given in the reference configuration: the fill keeps l0/2 from
  // the walls as written, not as moved to t = 0 (a tank starting at a small angle would
  // otherwise lose a row of particles on one side).
  erp::WallSet reference;
  for (std::size_t w = 0; w < scene.walls.size(); ++w)
    reference.add_polyline(scene.walls[w].polyline, scene.walls[w].closed, static_cast<int>(w));
  for (const auto& region : regions) {
    Vec2 origin = region.front();
    for (const auto& p : region) origin = origin.cwiseMin(p);
    const auto filled = erp::fill_lattice(origin, l0, {region}, holes, &reference);
    positions.insert(positions.end(), filled.begin(), filled.end());
    holes.push_back(region);
  }
  if (positions.empty())
    fail_at(scene, scene.fluid->line, "fluid.regions",
            "no particle fits in the regions at this l0");
  return positions;
}

BoxRegion read_box_region(Section& s, const std::string& what) {
  const bool doc = s.context().documenting();
  auto corner = [&](const std::string& key, const std::string& text) {
    const std::optional<Vec3> v = s.optional_vec3(key, what + ": " + text + " [x, y, z], m");
    if (!v && !doc) s.fail(key, "required key missing");
    return v.value_or(Vec3::Zero());
  };
  BoxRegion b;
  b.line = s.line();
  b.min = corner("min", "lowest corner");
  b.max = corner("max", "highest corner");
  if (!doc && !((b.max - b.min).minCoeff() > 0.0))
    s.fail("max", "must lie above min on every axis");
  s.finish();
  return b;
}

void read_box_area(Section& s, double l0, std::vector<BoxRegion>& regions,
                   std::optional<BoxRegion>& domain, bool other_regions) {
  for (auto& r : s.list("regions", "boxes filled with particles at spacing l0"))
    regions.push_back(read_box_region(r, "a box of fluid"));
  if (regions.empty() && !other_regions) s.fail("regions", "at least one region is required");
  for (std::size_t i = 0; i < regions.size(); ++i)
    if (l0 > (regions[i].max - regions[i].min).minCoeff())
      s.fail("l0", "particle spacing " + significant(l0, 3) + " m is larger than fluid region " +
                       std::to_string(i));
  if (auto d = s.block("domain", "particles leaving this box are removed and counted"))
    domain = read_box_region(*d, "the domain");
}

bool read_periodic_z(Section& s) {
  return s.boolean("periodic_z", false,
                   "(dimension 3) the fluid and the tank wrap along z over the tank's depth, a "
                   "whole number of l0: a slab with no walls behind its z faces (quasi-2-D runs); "
                   "needs tank, and a domain (if given) of the tank's z");
}

void check_periodic_z(Section& s, const std::optional<BoxRegion>& tank,
                      const std::optional<BoxRegion>& domain, double l0) {
  if (!tank) s.fail("periodic_z", "needs a tank (its depth along z is the period)");
  const double layers = (tank->max.z() - tank->min.z()) / l0;
  if (std::abs(layers - std::round(layers)) > 1e-9 * layers)
    s.fail("periodic_z", "the tank's depth " + significant(tank->max.z() - tank->min.z(), 6) +
                             " m is not a whole number of l0 = " + significant(l0, 6) +
                             " m (the lattice would not wrap)");
  if (domain && (domain->min.z() != tank->min.z() || domain->max.z() != tank->max.z()))
    s.fail("domain", "with periodic_z its z range must be the tank's (the period)");
}

std::string periodic_refusal(const Section& s, const std::string& key) {
  return s.message(key, "not yet supported under mpirun (issue 47): a periodic fluid cannot be "
                        "decomposed; run it without mpirun");
}

bool inside_box(const Vec3& p, const Vec3& lo, const Vec3& hi) {
  return (p - lo).minCoeff() >= 0.0 && (hi - p).minCoeff() >= 0.0;
}

particles::BlockRange fill_block(std::size_t n, const Ranks& ranks) {
  return ranks.decomposed() ? particles::block_of(n, ranks.rank(), ranks.size())
                            : particles::BlockRange{0, n};
}

std::pair<Vec3, Vec3> box_domain(const std::optional<BoxRegion>& domain,
                                 const std::optional<BoxRegion>& tank,
                                 std::span<const Vec3> tank_points,
                                 const std::vector<BoxRegion>& regions, double margin) {
  if (domain) return {domain->min, domain->max};
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  if (tank) lo = tank->min, hi = tank->max;
  for (const Vec3& p : tank_points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  for (const BoxRegion& r : regions) lo = lo.cwiseMin(r.min), hi = hi.cwiseMax(r.max);
  return {lo - Vec3::Constant(margin), hi + Vec3::Constant(margin)};
}

void check_box_regions(const Scene& scene, Section& s, std::vector<Section>& probes,
                       const std::vector<BoxRegion>& regions, const std::optional<BoxRegion>& tank,
                       const Vec3& domain_min, const Vec3& domain_max) {
  for (std::size_t i = 0; i < regions.size(); ++i) {
    const BoxRegion& r = regions[i];
    if (!inside_box(r.min, domain_min, domain_max) || !inside_box(r.max, domain_min, domain_max))
      s.fail("domain", "fluid region " + std::to_string(i) + " reaches outside the domain");
    if (tank &&
        (!inside_box(r.min, tank->min, tank->max) || !inside_box(r.max, tank->min, tank->max)))
      s.fail("regions", "fluid region " + std::to_string(i) + " reaches outside the tank");
  }
  for (std::size_t i = 0; i < scene.output.probes.size(); ++i) {
    const ProbeSpec& p = scene.output.probes[i];
    if (p.point3 && p.structure.empty() && !inside_box(*p.point3, domain_min, domain_max))
      probes[i].fail("point", "the point is outside the fluid domain");
  }
}

} // namespace fsi::app
