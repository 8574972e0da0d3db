// The FE structure as a plug-in: its scene keys (fem_scene.cpp), its checks against the scene,
// its model, fields, probes and memory footprint.
#include "fem/fem_plugin.hpp"

#include "fem/fem_model.hpp"
#include "fem/fem_model_t10.hpp"
#include "fsi/core/format.hpp"
#include "fsi_app/wall_motion.hpp"
#include "structure_geometry.hpp"

#include <algorithm>
#include <limits>
#include <set>
#include <sstream>

namespace fsi::app::fem_plugin {

namespace {

std::string count(double n) {
  return significant(n, 3);
}

// A structured T6 rectangle has (2 nx + 1)(2 ny + 1) nodes on a regular grid.
void check_rectangle_probe(const MeshSpec& m, const ProbeSpec& p, const Section& s) {
  const long nodes = (2L * m.elements_x + 1) * (2L * m.elements_y + 1);
  if (p.node && *p.node >= nodes)
    s.fail("node", "node " + std::to_string(*p.node) + " does not exist (the mesh has " +
                       std::to_string(nodes) + " nodes)");
  if (p.point) {
    const Vec2 h(m.width / (2 * m.elements_x), m.height / (2 * m.elements_y));
    const Vec2 grid = (*p.point - m.origin).cwiseQuotient(h);
    const Vec2 snapped = grid.array().round();
    const bool inside = snapped.x() >= 0 && snapped.x() <= 2 * m.elements_x && snapped.y() >= 0 &&
                        snapped.y() <= 2 * m.elements_y;
    if (!inside || (grid - snapped).cwiseAbs().maxCoeff() > 1e-6) {
      std::ostringstream msg;
      msg << "no node of structure '" << p.structure << "' at (" << p.point->x() << ", "
          << p.point->y() << ")";
      s.fail("point", msg.str());
    }
  }
}

void check(const Scene& scene, std::size_t index, Section& s, std::vector<Section>& probes) {
  const StructureBlock& block = scene.structures[index];
  const StructureSpec& st = block.as<StructureSpec>();
  if (st.mesh.kind != "gmsh") {
    const bool box = st.mesh.kind == "box";
    const std::set<std::string> tags =
        box ? std::set<std::string>(box_sides().begin(), box_sides().end())
            : std::set<std::string>{"left", "right", "bottom", "top"};
    const std::string sides = box ? "a box has left, right, bottom, top, back, front"
                                  : "a rectangle has left, right, bottom, top";
    auto check_tags = [&](const std::vector<std::string>& list, const std::string& key) {
      for (const auto& t : list)
        if (!tags.count(t)) s.fail(key, "unknown boundary tag '" + t + "' (" + sides + ")");
    };
    check_tags(st.clamped, "clamped");
    check_tags(st.sliding, "sliding");
    check_tags(st.interface, "interface");
    for (const auto& l : st.loads)
      if (!tags.count(l.boundary)) s.fail("loads", "unknown boundary tag '" + l.boundary + "'");
  }
  check_clamped_motion(scene, st.clamped_motion, !st.clamped.empty(), "clamped boundary tags", s);
  if (st.clamped_rigid_motion)
    check_motion_table(scene, *st.clamped_rigid_motion, st.clamped_rigid_motion_line,
                       s.path() + ".clamped_rigid_motion.table");
  if (scene.fluid && st.interface.empty()) // a fluid and a structure are coupled
    s.fail("interface", "a structure coupled to the fluid needs the boundary tags it is wetted on");
  for (std::size_t i = 0; i < scene.output.probes.size(); ++i) {
    const auto& p = scene.output.probes[i];
    if (p.structure != block.name) continue;
    if (!p.node && !p.point && !p.point3) probes[i].fail("", "give node or point");
    if (st.mesh.kind == "rectangle") check_rectangle_probe(st.mesh, p, probes[i]);
    check_frame_probe(p, st.clamped_motion, probes[i]);
  }
}

// A T10 box: (2 nx + 1)(2 ny + 1)(2 nz + 1) nodes, 6 nx ny nz elements. Per degree of freedom
// the sparse M, K and K_eff hold about 81 entries per row (27 nodes x 3), the Cholesky factor
// about 20 times the entries of K (3D nested dissection fill, an assumption), and about 16 state
// and work vectors; per element the 900 assembly triplets (16 B each).
Footprint box_footprint(const MeshSpec& m) {
  Footprint e;
  e.key = "mesh";
  const double nx = m.elements_x, ny = m.elements_y, nz = m.elements_z;
  const double nodes = (2 * nx + 1) * (2 * ny + 1) * (2 * nz + 1);
  const double elements = 6 * nx * ny * nz;
  const double row_entries = 81;
  const double per_dof = 3 * row_entries * 12 + 20 * row_entries * 12 + 16 * 8;
  e.count = elements;
  e.bytes = 3 * nodes * per_dof + elements * (900 * 16 + 10 * 4) + nodes * 3 * 8 * 2;
  e.counts = count(elements) + " T10 elements (6 elements_x elements_y elements_z)";
  if (elements * 10 * 81 > std::numeric_limits<int>::max()) // 30 dofs per element, 81 per row
    e.overflows.emplace_back(
        "mesh", count(elements) + " T10 elements: the sparse matrices would exceed 2^31 entries");
  return e;
}

// A structured T6 rectangle: (2 nx + 1)(2 ny + 1) nodes, 2 nx ny elements. Per degree of
// freedom the sparse M, K and K_eff hold about 26 entries per row (12 B each in CSR), the
// Cholesky factor about 8 times the entries of K (2D nested dissection fill, an assumption), and
// about 16 state and work vectors; per element the 144 assembly triplets (16 B each).
Footprint footprint(const Scene& scene, std::size_t index) {
  const StructureSpec& st = scene.structures[index].as<StructureSpec>();
  Footprint e;
  e.key = "mesh";
  if (st.mesh.kind == "box") return box_footprint(st.mesh);
  if (st.mesh.kind != "rectangle") return e; // a Gmsh mesh is bounded by its file
  const double nx = st.mesh.elements_x, ny = st.mesh.elements_y;
  const double nodes = (2 * nx + 1) * (2 * ny + 1);
  const double elements = 2 * nx * ny;
  const double dofs = 2 * nodes;
  const double row_entries = 26;
  const double per_dof = 3 * row_entries * 12 + 8 * row_entries * 12 + 16 * 8;
  const double per_element = 144 * 16 + 6 * 4 + 8;
  const double per_node = 16 + 16 + 8; // X, positions, node_label
  e.count = elements;
  e.bytes = dofs * per_dof + elements * per_element + nodes * per_node;
  e.counts = count(elements) + " T6 elements (2 elements_x elements_y)";
  if (elements * 4 * 26 >
      std::numeric_limits<int>::max()) // 2 dofs x 2 nodes per element, 26 per row
    e.overflows.emplace_back(
        "mesh", count(elements) + " T6 elements: the sparse matrices would exceed 2^31 entries");
  return e;
}

// The mesh (read or generated) and its tags; the outline the part would show.
StructureOutline validate(const Scene& scene, std::size_t index) {
  const StructureBlock& block = scene.structures[index];
  if (scene.dimension == 3) { // the 3-D interface (FemModelT10::interface_mesh3), no area
    StructureOutline o;
    o.interface3 =
        fem::interface_of(checked_tet_mesh(scene, block), block.as<StructureSpec>().interface).mesh;
    return o;
  }
  const fem::Mesh mesh = checked_mesh(scene, block);
  return {fem::interface_of(mesh, block.as<StructureSpec>().interface).mesh,
          occupied_triangles(mesh)};
}

std::unique_ptr<StructurePart> build(const Scene& scene, std::size_t index) {
  if (scene.dimension == 3) return make_structure_part<FemModelT10>(scene, index);
  return make_structure_part<FemModel>(scene, index);
}

} // namespace

StructurePlugin plugin() {
  return {"fem",
          "total-Lagrangian T6 (3-D: T10) finite elements, Newmark-beta, Newton-Raphson",
          read_structure,
          check,
          build,
          validate,
          footprint,
          {"displacement", "velocity", "von_mises"},
          {"displacement_x", "displacement_y", "displacement_z", "displacement_x_tank",
           "displacement_y_tank"},
          fem_from_tlsph};
}

} // namespace fsi::app::fem_plugin
