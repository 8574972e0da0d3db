#pragma once
// The T10 mesh of a 3-D solid in its reference configuration, with tagged boundary faces.
#include <array>
#include <string>
#include <vector>

#include "fsi/core/types.hpp"

namespace fsi::fem {

/// A quadratic boundary face: corners 0, 1, 2 then mid-nodes 3 (0-1), 4 (1-2), 5 (2-0), ordered
/// counter-clockwise seen from outside, so (X_1 - X_0) x (X_2 - X_0) points out of the solid.
struct BoundaryFace {
  std::array<int, 6> nodes;
  std::string tag;
};

struct TetMesh {
  std::vector<Vec3> X;                       ///< reference node coordinates [m]
  std::vector<std::array<int, 10>> elements; ///< T10, node order of shape_t10.hpp
  std::vector<BoundaryFace> faces;           ///< tagged boundary faces
  std::string source;                        ///< file name, or a description of the generator

  std::size_t num_nodes() const { return X.size(); }
  std::size_t num_elements() const { return elements.size(); }
  /// Sorted, unique nodes of the faces carrying `tag`. Throws InputError if no face has it.
  std::vector<int> node_set(const std::string& tag) const;
  /// The faces carrying `tag`. Throws InputError if there are none.
  std::vector<BoundaryFace> faces_with_tag(const std::string& tag) const;
};

/// Checks the mesh before any computation and throws InputError naming the element: node index
/// out of range, non-positive volume, or det J <= 0 at a quadrature point.
void validate_mesh(const TetMesh& mesh);

} // namespace fsi::fem
