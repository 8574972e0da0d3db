// The 3-D EMPS fluid's checks that need the fill and the walls (validate3): the fill's points in
// front of every wall triangle, the tank open only above its water.
#include "emps/emps_model3.hpp"
#include "emps/wall_point_pressure.hpp"

#include "fsi/core/error.hpp"
#include "fsi/core/format.hpp"
#include "fsi_app/wall_motion.hpp"
#include "geometry_erp/triangle_locator.hpp"

#include <algorithm>
#include <limits>
#include <span>
#include <sstream>
#include <string>

namespace fsi::app::emps_plugin {

namespace {

/// A point for messages: "(x, y, z) m", six significant digits.
std::string point_text(const Vec3& p) {
  std::ostringstream at;
  at << '(' << significant(p.x(), 6) << ", " << significant(p.y(), 6) << ", "
     << significant(p.z(), 6) << ") m";
  return at.str();
}

/// Refuses an open edge of the tank_file surface below the top of the fill (against gravity;
/// `x` this rank's block of it, the top the highest of every rank's): a hole the water can
/// leave by. A tank open above its water passes. Collective when decomposed.
void check_open_edges(const Scene& scene, const FluidSpec3& f, const std::vector<Vec3>& x,
                      const Ranks& ranks) {
  if (!f.tank_surface || f.tank_surface->open_edges == 0 || scene.gravity3.norm() == 0.0) return;
  const Vec3 up = -scene.gravity3.normalized();
  std::vector<double> tops(static_cast<std::size_t>(ranks.size()), 0.0); // each rank's top
  double& own = tops[static_cast<std::size_t>(ranks.rank())];
  own = -std::numeric_limits<double>::infinity();
  for (const Vec3& xi : x) own = std::max(own, up.dot(xi));
  ranks.sum(tops); // the others' entries are zero: every rank's top, on every rank
  const double top = *std::max_element(tops.begin(), tops.end());
  erp::TriangleWallSet surface;
  surface.add_triangles(f.tank_surface->points, f.tank_surface->triangles, 0);
  const auto& X = surface.nodes().x;
  for (std::size_t t = 0; t < surface.triangles().size(); ++t)
    for (std::size_t k = 0; k < 3; ++k) {
      const auto edge = static_cast<erp::TriangleFeature>(3 + k); // corners k, k + 1
      const Vec3& a = X[static_cast<std::size_t>(surface.triangles().node[t][k])];
      const Vec3& b = X[static_cast<std::size_t>(surface.triangles().node[t][(k + 1) % 3])];
      if (!surface.open(static_cast<int>(t), edge) || std::min(up.dot(a), up.dot(b)) >= top)
        continue;
      fail_at(scene, f.tank_line, "fluid.tank_file",
              f.tank_path + ": facet " + std::to_string(t + 1) + " has an open edge at " +
                  point_text(0.5 * (a + b)) +
                  " below the water's top (a hole the water can leave by; only a " +
                  "tank open above its water is allowed)");
    }
}

/// The line of the fluid's first region (a box, else region_file) for messages.
int regions_line(const FluidSpec3& f) {
  return f.regions.empty() ? f.region_line : f.regions.front().line;
}

/// InputError naming the key for the first of the fill's points `x` behind a wall triangle.
void check_behind_walls(const Scene& scene, const erp::TriangleWallSet& walls,
                        std::span<const Vec3> x) {
  const FluidSpec3& f = scene.fluid->as<FluidSpec3>();
  const erp::TriangleLocator locator(walls, f.options.r_e());
  erp::TriangleHits hits;
  locator.query(x, hits);
  for (std::size_t i = 0; i < x.size(); ++i)
    if (hits.crossed[i]) {
      const std::string at = point_text(x[i]);
      const int group = walls.triangles().group[static_cast<std::size_t>(hits.triangle[i])];
      if (group > 0)
        fail_at(scene, regions_line(f), "fluid.regions",
                "the fluid at " + at + " lies behind the interface of structure '" +
                    scene.structures[static_cast<std::size_t>(group - 1)].name + "'");
      if (f.tank_surface)
        fail_at(scene, f.tank_line, "fluid.tank_file",
                f.tank_path + ": the fluid at " + at + " lies behind facet " +
                    std::to_string(hits.triangle[i] + 1) +
                    " (each facet's normal must point into the fluid)");
      fail_at(scene, regions_line(f), "fluid.regions",
              "the fluid at " + at + " lies behind a wall of the tank");
    }
}

} // namespace

void validate3(const Scene& scene, const std::vector<InterfaceMesh3>& interfaces) {
  const OneProcess one{};
  validate3(scene, interfaces, fill_regions3(scene.fluid->as<FluidSpec3>(), one), one);
}

void validate3(const Scene& scene, const std::vector<InterfaceMesh3>& interfaces, const Fill3& fill,
               const Ranks& ranks) {
  const FluidSpec3& f = scene.fluid->as<FluidSpec3>();
  if (fill.total == 0)
    fail_at(scene, regions_line(f), f.regions.empty() ? "fluid.region_file" : "fluid.regions",
            "no particle fits");
  if (f.periodic_z && !scene.structures.empty()) throw InputError(f.periodic_structures);
  if (f.tank_motion) {
    if (!scene.structures.empty())
      fail_at(scene, f.tank_motion_line, "fluid.tank_motion", "not available with structures yet");
    if (!f.domain) // the box around the tank at rest would not hold it as it moves
      fail_at(scene, f.tank_motion_line, "fluid.tank_motion",
              "needs fluid.domain, a box that holds the tank as it moves");
    check_motion_table(scene, *f.tank_motion, f.tank_motion_line, "fluid.tank_motion.table");
  }
  check_open_edges(scene, f, fill.x, ranks);
  std::vector<erp::InterfaceTriangles> triangles;
  const std::unique_ptr<erp::TriangleWallSet> walls = fluid_walls(scene, interfaces, triangles);
  WallPointProbes(scene, *walls, f.options.r_e(), f.tank_motion || !interfaces.empty());
  if (walls->triangles().size() == 0) return;
  if (const auto motion = tank_motion(f, *walls)) motion->move(*walls, 0.0); // the fill at t = 0
  // Each rank its block of the fill (ids as one process numbers them, particles/setup_block.hpp):
  // the lowest failing rank holds the first particle behind a wall in id order.
  std::string failure;
  try {
    check_behind_walls(scene, *walls, fill.x);
  } catch (const InputError& e) {
    failure = e.what();
  }
  if (const std::string first = ranks.first(failure); !first.empty()) throw InputError(first);
}

} // namespace fsi::app::emps_plugin
