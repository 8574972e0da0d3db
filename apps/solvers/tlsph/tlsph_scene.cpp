// The TL-SPH solid's scene keys, each declared once where it is read.
#include "tlsph/tlsph_spec.hpp"

#include "fem/fem_model_t10.hpp"
#include "fsi/core/error.hpp"
#include "fsi_app/material_reader.hpp"
#include "structure_fem/gmsh_reader.hpp"
#include "tlsph/tlsph_mesh_outline.hpp"

#include <algorithm>

namespace fsi::app::tlsph_plugin {

namespace {

Box read_box(Section s, const std::string& what) {
  Box b;
  b.min = s.vec2("min", "lower-left corner of " + what + ", m");
  b.max = s.vec2("max", "upper-right corner, m");
  if (!s.context().documenting() && (b.max.x() <= b.min.x() || b.max.y() <= b.min.y()))
    s.fail("max", "must lie above and right of min");
  s.finish();
  return b;
}

// A 3-D scene's box: corners [x, y, z] (read outside documentation mode).
Box3 read_box3(Section s, const std::string& what) {
  const auto lo = s.optional_vec3("min", "smallest corner of " + what + ", m");
  const auto hi = s.optional_vec3("max", "largest corner, m");
  if (!lo) s.fail("min", "required key missing");
  if (!hi) s.fail("max", "required key missing");
  if (!((*hi - *lo).minCoeff() > 0.0)) s.fail("max", "must exceed min along x, y and z");
  s.finish();
  return {*lo, *hi};
}

// "a, b, c": the distinct names, sorted.
std::string listed(std::vector<std::string> names) {
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  std::string all;
  for (const auto& n : names) all += (all.empty() ? "" : ", ") + n;
  return all;
}

// A rectangle (sides tagged bottom, right, top, left), a counter-clockwise polygon with a tag
// per edge (default: every edge "boundary") or a Gmsh mesh's boundary (tlsph_mesh_outline.hpp).
void read_region(Section s, TlsphSpec& t) {
  const bool doc = s.context().documenting();
  if (!doc && s.context().dimension == 3) { // a box, filled by tlsph::fill_box
    for (const char* key : {"polygon", "file", "tags"})
      if (s.has(key)) s.fail(key, "is 2-D only (a 3-D region is a box: min, max)");
    t.box = read_box3(s, "the box filled with particles at dp from it");
    return;
  }
  if (doc || s.has("file")) {
    const auto file = s.file(
        "file", "Gmsh .msh of the region, as the fem type's mesh.file (format 4.1 ASCII or "
                "binary, or 2.2 ASCII; 6-node triangles): its boundary, one loop without holes, "
                "filled like a polygon; each edge tagged with its line's physical group (none: "
                "'boundary')");
    if (!doc && s.has("polygon")) s.fail("file", "give a polygon or a file, not both");
    if (!doc) try {
        MeshOutline mesh = mesh_outline(fem::read_gmsh(file.string()));
        t.outline = std::move(mesh.outline), t.tags = std::move(mesh.tags);
      } catch (const InputError& e) {
        s.fail("file", e.what());
      }
  }
  if (doc || s.has("polygon")) {
    t.outline = s.points("polygon", 3,
                         "counter-clockwise polygon filled with particles (lattice from the lower-"
                         "left corner of its box), m");
    t.tags = s.names("tags", {},
                     "a tag per polygon edge, edge i from vertex i to i + 1 "
                     "(default: every edge 'boundary')");
    if (!doc && t.tags.empty()) t.tags.assign(t.outline.size(), "boundary");
    if (!doc && t.tags.size() != t.outline.size())
      s.fail("tags", std::to_string(t.tags.size()) + " tags for " +
                         std::to_string(t.outline.size()) + " polygon edges");
    double twice = 0.0;
    for (std::size_t i = 0; i < t.outline.size(); ++i) {
      const Vec2 &a = t.outline[i], &b = t.outline[(i + 1) % t.outline.size()];
      twice += a.x() * b.y() - b.x() * a.y();
    }
    if (!doc && !(twice > 0.0)) s.fail("polygon", "must be counter-clockwise (solid on the left)");
  }
  if (doc || (!s.has("polygon") && !s.has("file"))) {
    const Vec2 lo = s.vec2("min", "lower-left corner of a rectangle filled with particles at dp "
                                  "from it; sides tagged bottom, right, top, left, m (3-D: "
                                  "[x, y, z], a box's smallest corner)");
    const Vec2 hi = s.vec2("max", "upper-right corner, m");
    if (!doc && (hi.x() <= lo.x() || hi.y() <= lo.y()))
      s.fail("max", "must lie above and right of min");
    if (!doc) {
      t.outline = {lo, {hi.x(), lo.y()}, hi, {lo.x(), hi.y()}};
      t.tags = {"bottom", "right", "top", "left"};
    }
  }
  s.finish();
}

} // namespace

std::shared_ptr<const SolverSpec> read_tlsph(Section& s) {
  auto spec = std::make_shared<TlsphSpec>();
  TlsphSpec& t = *spec;
  const bool doc = s.context().documenting();
  const bool three_d = !doc && s.context().dimension == 3;
  read_region(s.required_block("region", "the solid: a rectangle (min, max), a polygon or a Gmsh "
                                         "mesh (file)"),
              t);
  OptionReader reader(s);
  tlsph::visit_options(t.options, reader);
  auto mat = s.required_block("material", "hyperelastic material (materials/)");
  read_material(mat, t.options.material);
  for (auto& box : s.list("clamped", "boxes: the particles whose reference position lies inside "
                                     "are the clamp, a support beyond the body (fixed: the body "
                                     "is clamped at the box's face, so the region extends 2 or "
                                     "more rows into the box; or they follow clamped_motion)"))
    if (three_d)
      t.clamped3.push_back(read_box3(box, "a clamped box"));
    else
      t.clamped.push_back(read_box(box, "a clamped box"));
  t.clamped_motion = s.text("clamped_motion", "",
                            "name of a wall with a motion: the clamped particles follow its rigid "
                            "motion; empty: they stay fixed");
  t.options.interface_tags =
      s.names("interface", {},
              "region edge tags wetted by the fluid (a rectangle: bottom, right, top, left; a "
              "3-D box: its faces left, right, bottom, top, back, front, as the fem type's)");
  if (three_d) { // no walls; the interface on the box's faces, named as the fem type's
    if (!t.clamped_motion.empty())
      s.fail("clamped_motion", "is 2-D only (3-D scenes: fixed clamps)");
    const auto& faces = fem_plugin::box_sides();
    for (const auto& tag : t.options.interface_tags)
      if (std::find(faces.begin(), faces.end(), tag) == faces.end())
        s.fail("interface",
               "no face of the box is named '" + tag + "' (left, right, bottom, top, back, front)");
    if (t.options.interface_particles)
      s.fail("interface_particles", "is 2-D only (a 3-D TL-SPH solid couples through its box's "
                                    "faces)");
    const Vec3 size = t.box.max - t.box.min;
    if (t.options.dp * 3.0 > size.minCoeff())
      s.fail("dp", "fewer than 3 particles across the region (" + std::to_string(size.x()) + " x " +
                       std::to_string(size.y()) + " x " + std::to_string(size.z()) + " m)");
  } else if (!doc) {
    Vec2 lo = t.outline.front(), hi = lo;
    for (const Vec2& p : t.outline) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    const Vec2 size = hi - lo;
    if (t.options.dp * 3.0 > size.minCoeff())
      s.fail("dp", "fewer than 3 particles across the region (" + std::to_string(size.x()) + " x " +
                       std::to_string(size.y()) + " m)");
    for (const auto& tag : t.options.interface_tags)
      if (std::find(t.tags.begin(), t.tags.end(), tag) == t.tags.end())
        s.fail("interface", "no region edge is tagged '" + tag +
                                "' (the region's tags: " + listed(t.tags) + ")");
  }
  return spec;
}

} // namespace fsi::app::tlsph_plugin
