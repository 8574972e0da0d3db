#include "structure_geometry.hpp"

#include "fem/fem_model_t10.hpp"
#include "fem/fem_spec.hpp"
#include "fsi/core/error.hpp"
#include "fsi_app/solver_plugin.hpp"
#include "structure_fem/gmsh_reader.hpp"
#include "tlsph/tlsph_mesh_outline.hpp"
#include "tlsph/tlsph_spec.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

namespace fsi::app {

namespace {

using KeyValue = std::pair<YAML::Node, YAML::Node>;

// The entry's value of `key`, given in the entry or in its block named `type`; undefined if
// neither. Its key's line in `line`.
YAML::Node given(const YAML::Node& entry, const std::string& type, const std::string& key,
                 int& line) {
  for (const YAML::Node& block : {entry, entry[type]})
    if (block.IsDefined() && block.IsMap())
      for (auto it = block.begin(); it != block.end(); ++it)
        if (it->first.Scalar() == key && !it->second.IsNull()) {
          line = it->first.Mark().line + 1;
          return it->second;
        }
  return YAML::Node(YAML::NodeType::Undefined);
}

bool given(const YAML::Node& entry, const std::string& type, const std::string& key) {
  int line = 0;
  return given(entry, type, key, line).IsDefined();
}

// A key named `name` marked at line `line` of the scene: a message about a key derived from
// another names the line of the key it was derived from.
YAML::Node key_at(const std::string& name, int line) {
  return YAML::Load(std::string(static_cast<std::size_t>(std::max(line - 1, 0)), '\n') + name);
}

YAML::Node point(const Vec2& p) {
  YAML::Node n(YAML::NodeType::Sequence);
  n.push_back(p.x());
  n.push_back(p.y());
  return n;
}

YAML::Node point3(const Vec3& p) {
  YAML::Node n(YAML::NodeType::Sequence);
  n.push_back(p.x());
  n.push_back(p.y());
  n.push_back(p.z());
  return n;
}

YAML::Node map_at(int line, const std::vector<std::pair<std::string, YAML::Node>>& pairs) {
  YAML::Node n(YAML::NodeType::Map);
  for (const auto& [key, value] : pairs) n.force_insert(key_at(key, line), value);
  return n;
}

std::set<std::string> only_in(const std::set<std::string>& a, const std::set<std::string>& b) {
  std::set<std::string> out;
  std::set_difference(a.begin(), a.end(), b.begin(), b.end(), std::inserter(out, out.end()));
  return out;
}

// The other type's reading of the entry: the keys its reader declares and its block, lifted.
Section read_as(const Section& s, const std::string& type,
                const std::function<std::shared_ptr<const SolverSpec>(Section&)>& read,
                std::shared_ptr<const SolverSpec>& spec) {
  const std::set<std::string> own = declared_keys(read);
  YAML::Node view(YAML::NodeType::Map);
  for (auto it = s.node().begin(); it != s.node().end(); ++it)
    if (own.count(it->first.Scalar()) || it->first.Scalar() == type)
      view.force_insert(it->first, it->second);
  Section other(view, s.path(), s.context(), s.line());
  other.lift(type);
  spec = read(other);
  other.finish();
  return other;
}

// The entry as type `self` reads it: the keys only type `other` declares (and `clamped`, in
// the other type's form) moved to the other type's block, which the scene reader then checks
// and sets aside; `added` put in the block of `self`, which the reader lifts.
YAML::Node adopted(const Section& s, const std::string& self, const std::string& other,
                   const std::set<std::string>& moved, const std::vector<KeyValue>& added) {
  YAML::Node view(YAML::NodeType::Map), own(YAML::NodeType::Map), others(YAML::NodeType::Map);
  YAML::Node own_key = key_at(self, s.line()), other_key = key_at(other, s.line());
  auto take = [](YAML::Node& key, YAML::Node& block, const auto& it) {
    key = it->first;
    if (it->second.IsMap())
      for (auto b = it->second.begin(); b != it->second.end(); ++b)
        block.force_insert(b->first, b->second);
  };
  for (auto it = s.node().begin(); it != s.node().end(); ++it) {
    const std::string key = it->first.Scalar();
    if (key == self)
      take(own_key, own, it);
    else if (key == other)
      take(other_key, others, it);
    else if (moved.count(key) || key == "clamped")
      others.force_insert(it->first, it->second);
    else
      view.force_insert(it->first, it->second);
  }
  for (const auto& [key, value] : added) own.force_insert(key, value);
  view.force_insert(own_key, own);
  view.force_insert(other_key, others);
  return view;
}

std::string at(const Vec2& p) {
  std::ostringstream s;
  s << "(" << p.x() << ", " << p.y() << ")";
  return s.str();
}

// An FE mesh's outline (counter-clockwise, a tag per edge) and its node spacing.
struct Outline {
  std::vector<Vec2> points;
  std::vector<std::string> tags;
  double spacing = 0.0;
};

Outline outline_of(const fem_plugin::MeshSpec& m, const Section& fe) {
  if (m.kind == "rectangle") {
    const Vec2 lo = m.origin, hi = m.origin + Vec2(m.width, m.height);
    return {{lo, {hi.x(), lo.y()}, hi, {lo.x(), hi.y()}},
            {"bottom", "right", "top", "left"},
            std::min(m.width / (2 * m.elements_x), m.height / (2 * m.elements_y))};
  }
  try {
    const fem::Mesh mesh = fem::read_gmsh(m.file.string());
    tlsph_plugin::MeshOutline loop = tlsph_plugin::mesh_outline(mesh);
    double sum = 0.0;
    for (const auto& el : mesh.elements)
      for (std::size_t k = 0; k < 3; ++k)
        sum +=
            (mesh.X[static_cast<std::size_t>(el[k])] - mesh.X[static_cast<std::size_t>(el[k + 3])])
                .norm();
    return {std::move(loop.outline), std::move(loop.tags),
            sum / (3.0 * static_cast<double>(mesh.elements.size()))};
  } catch (const InputError& e) {
    fe.fail("mesh", e.what());
  }
}

// The TL-SPH dp: the entry's, or the mesh's node spacing (then added as a key).
double particle_spacing(const YAML::Node& entry, double mesh_spacing, int mesh_line,
                        std::vector<KeyValue>& added) {
  int dp_line = 0;
  double dp = mesh_spacing;
  const YAML::Node dp_given = given(entry, "tlsph", "dp", dp_line);
  if (!dp_given.IsDefined())
    added.emplace_back(key_at("dp", mesh_line), dp);
  else if (!YAML::convert<double>::decode(dp_given, dp) || !(dp > 0.0))
    dp = mesh_spacing; // the TL-SPH reader names the bad dp
  return dp;
}

// 3-D: the T10 box as a TL-SPH box (nodes dp apart), each clamped side continued outwards by
// kClampRows dp into a clamped box spanning the region across.
std::vector<KeyValue> box_region(const YAML::Node& entry, const fem_plugin::StructureSpec& fe,
                                 const Section& fe_keys, int mesh_line) {
  const fem_plugin::MeshSpec& m = fe.mesh;
  if (m.kind != "box")
    fe_keys.fail("mesh", "a Gmsh T10 mesh does not translate to a 3-D TL-SPH solid (a box does; "
                         "or give the TL-SPH region in a tlsph block)");
  const Vec3 size(m.width, m.height, m.depth);
  const Vec3 cells(m.elements_x, m.elements_y, m.elements_z);
  std::vector<KeyValue> added;
  const double dp =
      particle_spacing(entry, (size.array() / (2.0 * cells.array())).minCoeff(), mesh_line, added);
  const auto& sides = fem_plugin::box_sides();
  Vec3 lo = m.origin3, hi = m.origin3 + size;
  for (const auto& tag : fe.clamped) {
    const auto k = std::find(sides.begin(), sides.end(), tag) - sides.begin();
    if (k == static_cast<std::ptrdiff_t>(sides.size()))
      fe_keys.fail("clamped", "no side of the box is tagged '" + tag +
                                  "' (left, right, bottom, top, back, front)");
    if (k % 2)
      hi[k / 2] += kClampRows * dp;
    else
      lo[k / 2] -= kClampRows * dp;
  }
  int clamped_line = 0;
  given(entry, "fem", "clamped", clamped_line);
  YAML::Node boxes(YAML::NodeType::Sequence);
  for (const auto& tag : fe.clamped) {
    const auto k = std::find(sides.begin(), sides.end(), tag) - sides.begin();
    Vec3 bmin = lo, bmax = hi; // the support: the rows beyond the side's face
    if (k % 2)
      bmin[k / 2] = m.origin3[k / 2] + size[k / 2];
    else
      bmax[k / 2] = m.origin3[k / 2];
    boxes.push_back(map_at(clamped_line, {{"min", point3(bmin)}, {"max", point3(bmax)}}));
  }
  added.emplace_back(key_at("region", mesh_line),
                     map_at(mesh_line, {{"min", point3(lo)}, {"max", point3(hi)}}));
  if (boxes.size() > 0) added.emplace_back(key_at("clamped", clamped_line), boxes);
  return added;
}

} // namespace

void tlsph_from_fem(Section& s) {
  const YAML::Node& entry = s.node();
  int mesh_line = 0, clamped_line = 0;
  if (given(entry, "tlsph", "region") || !given(entry, "fem", "mesh", mesh_line).IsDefined())
    return;
  std::shared_ptr<const SolverSpec> spec;
  const Section fe_keys = read_as(s, "fem", fem_plugin::read_structure, spec);
  const auto& fe = static_cast<const fem_plugin::StructureSpec&>(*spec);
  if (!fe.loads.empty())
    fe_keys.fail("loads", "a TL-SPH solid takes no constant loads: with loads the entry is of "
                          "type fem only");
  if (!fe.sliding.empty())
    fe_keys.fail("sliding", "a TL-SPH solid has no sliding faces: with sliding the entry is of "
                            "type fem only");
  if (fe.clamped_rigid_motion)
    fe_keys.fail("clamped_rigid_motion", "a 3-D TL-SPH solid's clamps are fixed: with a moving "
                                         "clamp the entry is of type fem only");
  const std::set<std::string> moved =
      only_in(declared_keys(fem_plugin::read_structure), declared_keys(tlsph_plugin::read_tlsph));
  if (s.context().dimension == 3) {
    s.rebind(adopted(s, "tlsph", "fem", moved, box_region(entry, fe, fe_keys, mesh_line)));
    return;
  }
  const Outline o = outline_of(fe.mesh, fe_keys);
  std::vector<KeyValue> added;
  const double dp = particle_spacing(entry, o.spacing, mesh_line, added);
  // Each clamped side continued outwards by kClampRows dp into a box, the support.
  given(entry, "fem", "clamped", clamped_line);
  std::vector<Vec2> points;
  std::vector<std::string> tags;
  YAML::Node boxes(YAML::NodeType::Sequence);
  const std::size_t n = o.points.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 &a = o.points[i], &b = o.points[(i + 1) % n];
    if (std::find(fe.clamped.begin(), fe.clamped.end(), o.tags[i]) == fe.clamped.end()) {
      points.push_back(a), tags.push_back(o.tags[i]);
      continue;
    }
    if (std::count(o.tags.begin(), o.tags.end(), o.tags[i]) != 1)
      fe_keys.fail("clamped", "the side '" + o.tags[i] +
                                  "' is more than one straight side of the mesh's outline; a "
                                  "TL-SPH clamp is one straight side (give the TL-SPH region "
                                  "and clamped boxes in a tlsph block)");
    const Vec2 d = b - a;
    if (std::min(std::abs(d.x()), std::abs(d.y())) > 1e-9 * d.norm())
      fe_keys.fail("clamped", "the side '" + o.tags[i] + "' from " + at(a) + " to " + at(b) +
                                  " is not parallel to an axis; TL-SPH clamps are boxes (give the "
                                  "TL-SPH region and clamped boxes in a tlsph block)");
    const Vec2 out = kClampRows * dp * Vec2(d.y(), -d.x()) / d.norm();
    for (const Vec2& p : {a, Vec2(a + out), Vec2(b + out)})
      points.push_back(p), tags.push_back("clamp");
    boxes.push_back(map_at(
        clamped_line, {{"min", point(a.cwiseMin(b + out))}, {"max", point(a.cwiseMax(b + out))}}));
  }
  for (const auto& tag : fe.clamped)
    if (std::find(o.tags.begin(), o.tags.end(), tag) == o.tags.end())
      fe_keys.fail("clamped", "no side of the mesh is tagged '" + tag + "'");
  YAML::Node polygon(YAML::NodeType::Sequence), names(YAML::NodeType::Sequence);
  for (const Vec2& p : points) polygon.push_back(point(p));
  for (const auto& t : tags) names.push_back(t);
  added.emplace_back(key_at("region", mesh_line),
                     map_at(mesh_line, {{"polygon", polygon}, {"tags", names}}));
  if (boxes.size() > 0) added.emplace_back(key_at("clamped", clamped_line), boxes);
  s.rebind(adopted(s, "tlsph", "fem", moved, added));
}

void fem_from_tlsph(Section& s) {
  if (s.context().dimension == 3) return; // 3-D: no 2-D region to mesh
  const YAML::Node& entry = s.node();
  int region_line = 0, clamped_line = 0;
  const YAML::Node region = given(entry, "tlsph", "region", region_line);
  if (given(entry, "fem", "mesh") || !region.IsDefined()) return;
  std::shared_ptr<const SolverSpec> spec;
  const Section ts = read_as(s, "tlsph", tlsph_plugin::read_tlsph, spec);
  const auto& t = static_cast<const tlsph_plugin::TlsphSpec&>(*spec);
  given(entry, "tlsph", "clamped", clamped_line);
  std::vector<KeyValue> added;
  if (region["file"].IsDefined()) {
    if (!t.clamped.empty())
      ts.fail("clamped", "TL-SPH clamped boxes do not translate to the FE mesh's boundary tags "
                         "(give the FE mesh and clamped tags in a fem block)");
    added.emplace_back(
        key_at("mesh", region_line),
        map_at(region_line, {{"kind", YAML::Node("gmsh")}, {"file", region["file"]}}));
  } else if (region["polygon"].IsDefined()) {
    ts.fail("region", "a TL-SPH polygon does not translate to an FE mesh (a rectangle {min, max} "
                      "or a Gmsh file does; or give the FE mesh in a fem block)");
  } else {
    // The rectangle less each clamped box's strip: the body ends at the box's face.
    Vec2 lo = t.outline[0], hi = t.outline[2];
    const Vec2 region_lo = lo, region_hi = hi;
    const double tol = 1e-6 * t.options.dp;
    YAML::Node sides(YAML::NodeType::Sequence);
    for (std::size_t k = 0; k < t.clamped.size(); ++k) {
      const tlsph_plugin::Box& b = t.clamped[k];
      const bool across_x = b.min.x() <= region_lo.x() + tol && b.max.x() >= region_hi.x() - tol;
      const bool across_y = b.min.y() <= region_lo.y() + tol && b.max.y() >= region_hi.y() - tol;
      std::string side;
      if (across_x && b.min.y() <= region_lo.y() + tol && b.max.y() < region_hi.y() - tol)
        side = "bottom", lo.y() = std::max(lo.y(), b.max.y());
      else if (across_x && b.max.y() >= region_hi.y() - tol && b.min.y() > region_lo.y() + tol)
        side = "top", hi.y() = std::min(hi.y(), b.min.y());
      else if (across_y && b.min.x() <= region_lo.x() + tol && b.max.x() < region_hi.x() - tol)
        side = "left", lo.x() = std::max(lo.x(), b.max.x());
      else if (across_y && b.max.x() >= region_hi.x() - tol && b.min.x() > region_lo.x() + tol)
        side = "right", hi.x() = std::min(hi.x(), b.min.x());
      else
        ts.fail("clamped", "box " + std::to_string(k) + " " + at(b.min) + " - " + at(b.max) +
                               " is not the strip of one side of the region " + at(region_lo) +
                               " - " + at(region_hi) + ", so it is no FE clamped side");
      sides.push_back(side);
    }
    if (!(hi.x() > lo.x() && hi.y() > lo.y()))
      ts.fail("clamped", "the clamped boxes leave no body of the region");
    const Vec2 size = hi - lo;
    auto elements = [&](double length) {
      return std::max(1L, std::lround(length / (2.0 * t.options.dp)));
    };
    added.emplace_back(key_at("mesh", region_line),
                       map_at(region_line, {{"kind", YAML::Node("rectangle")},
                                            {"origin", point(lo)},
                                            {"width", YAML::Node(size.x())},
                                            {"height", YAML::Node(size.y())},
                                            {"elements_x", YAML::Node(elements(size.x()))},
                                            {"elements_y", YAML::Node(elements(size.y()))}}));
    if (sides.size() > 0) added.emplace_back(key_at("clamped", clamped_line), sides);
  }
  s.rebind(adopted(
      s, "fem", "tlsph",
      only_in(declared_keys(tlsph_plugin::read_tlsph), declared_keys(fem_plugin::read_structure)),
      added));
}

} // namespace fsi::app
