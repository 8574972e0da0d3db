#include "structure_fem/mesh.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <utility>

#include "duplicate_nodes.hpp"
#include "fsi/core/error.hpp"
#include "structure_fem/element_t6.hpp"
#include "structure_fem/tagged_boundary.hpp"

namespace fsi::fem {

bool Mesh::has_tag(const std::string& tag) const {
  return std::any_of(edges.begin(), edges.end(), [&](const auto& e) { return e.tag == tag; });
}

std::vector<BoundaryEdge> Mesh::edges_with_tag(const std::string& tag) const {
  return facets_with_tag(edges, tag, source, "edge");
}

std::vector<int> Mesh::node_set(const std::string& tag) const {
  return facet_node_set(edges, tag, source, "edge");
}

namespace {

/// "source:line: " or "source: ".
std::string where(const Mesh& mesh, const std::vector<int>& lines, std::size_t i) {
  std::ostringstream s;
  s << mesh.source;
  if (i < lines.size()) s << ':' << lines[i];
  s << ": ";
  return s.str();
}

long label(const std::vector<long>& labels, std::size_t i) {
  return i < labels.size() ? labels[i] : static_cast<long>(i);
}

} // namespace

void validate_mesh(const Mesh& mesh, const MeshSourceLines& lines) {
  const std::size_t n_nodes = mesh.num_nodes();
  auto node_name = [&](std::size_t k) {
    return "node " + std::to_string(label(mesh.node_label, k));
  };
  auto element_name = [&](std::size_t e) {
    return "element " + std::to_string(label(mesh.element_label, e));
  };
  if (mesh.elements.empty()) throw InputError(mesh.source + ": the mesh has no T6 elements");

  std::vector<char> used(n_nodes, 0);
  for (std::size_t e = 0; e < mesh.num_elements(); ++e)
    for (int k : mesh.elements[e]) {
      if (k < 0 || static_cast<std::size_t>(k) >= n_nodes)
        throw InputError(where(mesh, lines.element_line, e) + element_name(e) + ": node index " +
                         std::to_string(k) + " out of range");
      used[static_cast<std::size_t>(k)] = 1;
    }
  for (std::size_t k = 0; k < n_nodes; ++k)
    if (!used[k])
      throw InputError(where(mesh, lines.node_line, k) + node_name(k) +
                       ": unused node (belongs to no element)");

  // Duplicate nodes: same coordinates up to 1e-10 of the bounding-box diagonal.
  Vec2 lo = mesh.X[0], hi = mesh.X[0];
  for (const auto& x : mesh.X) lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
  const double diag = std::hypot(hi.x() - lo.x(), hi.y() - lo.y()); // no overflow at 1e160 m
  const double tol = 1e-10 * diag;
  if (const auto pair = duplicate_nodes(mesh.X, tol)) {
    const auto [a, b] = *pair;
    throw InputError(where(mesh, lines.node_line, b) + node_name(b) +
                     ": duplicate node (same coordinates as " + node_name(a) + ")");
  }

  for (std::size_t e = 0; e < mesh.num_elements(); ++e) {
    ElementNodes X;
    for (std::size_t k = 0; k < 6; ++k)
      X[k] = mesh.X[static_cast<std::size_t>(mesh.elements[e][k])];
    const double area = t6_area(X);
    if (!std::isfinite(area))
      throw InputError(where(mesh, lines.element_line, e) + element_name(e) +
                       ": area is not a finite number (coordinates too large)");
    if (std::abs(area) <= 1e-12 * diag * diag)
      throw InputError(where(mesh, lines.element_line, e) + element_name(e) +
                       ": zero-area element");
    if (area < 0.0)
      throw InputError(where(mesh, lines.element_line, e) + element_name(e) +
                       ": inverted element (corners ordered clockwise)");
    if (t6_min_jacobian(X) <= 0.0)
      throw InputError(where(mesh, lines.element_line, e) + element_name(e) +
                       ": inverted element (det J <= 0 inside; mid-node too far from its edge "
                       "midpoint)");
  }

  // Every boundary edge must be an element side, with the solid on its left.
  std::map<std::pair<int, int>, std::array<int, 3>> sides; // (first, last corner) -> side
  for (const auto& el : mesh.elements)
    for (int s = 0; s < 3; ++s) {
      const std::array<int, 3> side{el[static_cast<std::size_t>(s)],
                                    el[static_cast<std::size_t>(s + 3)],
                                    el[static_cast<std::size_t>((s + 1) % 3)]};
      sides[{side[0], side[2]}] = side;
    }
  for (const auto& edge : mesh.edges) {
    const auto it = sides.find({edge.nodes[0], edge.nodes[2]});
    if (it == sides.end() || it->second != edge.nodes)
      throw InputError(mesh.source + ": boundary edge \"" + edge.tag + "\" (" +
                       node_name(static_cast<std::size_t>(edge.nodes[0])) + ", " +
                       node_name(static_cast<std::size_t>(edge.nodes[1])) + ", " +
                       node_name(static_cast<std::size_t>(edge.nodes[2])) +
                       ") is not an element side with the solid on its left");
  }
}

} // namespace fsi::fem
