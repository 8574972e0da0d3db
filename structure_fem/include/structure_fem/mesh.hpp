#pragma once
// The T6 mesh of the solid in its reference configuration, with tagged boundary edges.
#include <array>
#include <string>
#include <vector>

#include "structure_fem/types.hpp"

namespace fsi::fem {

/// A quadratic boundary edge (corner, mid, corner), oriented so that the solid lies on its left:
/// walking from nodes[0] to nodes[2], the outward normal points to the right, n = (t_y, -t_x).
struct BoundaryEdge {
  std::array<int, 3> nodes;
  std::string tag;
};

struct Mesh {
  std::vector<Vec2> X; ///< reference node coordinates [m]
  std::vector<std::array<int, 6>>
      elements;                    ///< T6, corners 0,1,2 then mids 3 (0-1), 4 (1-2), 5 (2-0), CCW
  std::vector<BoundaryEdge> edges; ///< tagged boundary edges
  std::vector<long> node_label;    ///< node ids as in the source (for messages)
  std::vector<long> element_label; ///< element ids as in the source (for messages)
  std::string source;              ///< file name, or a description of the generator

  std::size_t num_nodes() const { return X.size(); }
  std::size_t num_elements() const { return elements.size(); }
  bool has_tag(const std::string& tag) const;
  /// Sorted, unique nodes of the edges carrying `tag`. Throws InputError if no edge has it.
  std::vector<int> node_set(const std::string& tag) const;
  /// The edges carrying `tag`. Throws InputError if there are none.
  std::vector<BoundaryEdge> edges_with_tag(const std::string& tag) const;
};

/// Where each node and element was read from, for `file:line` messages; empty when generated.
struct MeshSourceLines {
  std::vector<int> node_line, element_line;
};

/// Checks the mesh before any computation and throws InputError naming the element or node:
/// index out of range, unused node, duplicate node (same coordinates), zero-area or inverted
/// element (det J <= 0 at a corner or at a quadrature point of the stiffness or mass rule, so
/// curved mid-nodes are accepted when they keep the map invertible), edge not on an element side.
void validate_mesh(const Mesh& mesh, const MeshSourceLines& lines = {});

} // namespace fsi::fem
