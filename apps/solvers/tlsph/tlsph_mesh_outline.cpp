#include "tlsph/tlsph_mesh_outline.hpp"

#include "fsi/core/error.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <utility>

namespace fsi::app::tlsph_plugin {

namespace {

using Side = std::pair<int, int>; // directed corner pair, the solid on its left

struct Next {
  int to, mid;
};

std::string node_name(const fem::Mesh& mesh, int k) {
  const auto i = static_cast<std::size_t>(k);
  std::ostringstream s;
  s << "node " << (i < mesh.node_label.size() ? mesh.node_label[i] : k) << " (" << mesh.X[i].x()
    << ", " << mesh.X[i].y() << ")";
  return s.str();
}

} // namespace

MeshOutline mesh_outline(const fem::Mesh& mesh) {
  std::map<Side, int> mid_of; // every element side, counter-clockwise in its element
  for (const auto& el : mesh.elements)
    for (std::size_t s = 0; s < 3; ++s) mid_of[{el[s], el[(s + 1) % 3]}] = el[s + 3];
  std::map<Side, std::string> tag_of;
  for (const auto& e : mesh.edges) {
    const auto [it, added] = tag_of.emplace(Side{e.nodes[0], e.nodes[2]}, e.tag);
    if (!added && it->second != e.tag)
      throw InputError(mesh.source + ": the boundary side from " + node_name(mesh, e.nodes[0]) +
                       " to " + node_name(mesh, e.nodes[2]) + " is in two physical groups, '" +
                       it->second + "' and '" + e.tag + "' (a side has one tag)");
  }
  std::map<int, Next> next; // boundary: the sides whose reverse is on no element
  for (const auto& [side, mid] : mid_of) {
    if (mid_of.count({side.second, side.first})) continue;
    if (!next.emplace(side.first, Next{side.second, mid}).second)
      throw InputError(mesh.source + ": the boundary touches itself at " +
                       node_name(mesh, side.first) + " (a region is one closed loop)");
  }
  // One loop from the first boundary corner; any side left over is a hole or a second body.
  MeshOutline all;
  int corner = next.begin()->first;
  std::size_t sides = 0;
  do {
    const Next& n = next.at(corner);
    const auto it = tag_of.find({corner, n.to});
    const std::string tag = it == tag_of.end() ? "boundary" : it->second;
    for (const int k : {corner, n.mid}) {
      all.outline.push_back(mesh.X[static_cast<std::size_t>(k)]);
      all.tags.push_back(tag);
    }
    corner = n.to, ++sides;
  } while (corner != next.begin()->first && sides <= next.size());
  if (sides != next.size())
    throw InputError(mesh.source + ": the boundary is more than one loop (" +
                     std::to_string(next.size() - sides) + " sides off the loop through " +
                     node_name(mesh, next.begin()->first) +
                     "): a hole or a second body; a region is one body without holes");
  // Merge collinear runs of one tag: vertex v stays unless its two edges share tag and line.
  const std::size_t m = all.outline.size();
  MeshOutline out;
  std::size_t first = 0;
  for (std::size_t v = 0; v < m; ++v) {
    const std::size_t before = (v + m - 1) % m;
    const Vec2 a = all.outline[v] - all.outline[before],
               b = all.outline[(v + 1) % m] - all.outline[v];
    const bool straight =
        std::abs(a.x() * b.y() - a.y() * b.x()) <= 1e-10 * a.norm() * b.norm() && a.dot(b) > 0.0;
    if (straight && all.tags[before] == all.tags[v]) continue;
    const Vec2& X = all.outline[v];
    if (!out.outline.empty()) {
      const Vec2& low = out.outline[first];
      if (X.y() < low.y() || (X.y() == low.y() && X.x() < low.x())) first = out.outline.size();
    }
    out.outline.push_back(X);
    out.tags.push_back(all.tags[v]);
  }
  std::rotate(out.outline.begin(), out.outline.begin() + static_cast<long>(first),
              out.outline.end());
  std::rotate(out.tags.begin(), out.tags.begin() + static_cast<long>(first), out.tags.end());
  return out;
}

} // namespace fsi::app::tlsph_plugin
