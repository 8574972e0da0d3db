#include "structure_fem/mesh_t10.hpp"

#include <string>

#include "fsi/core/error.hpp"
#include "structure_fem/element_t10.hpp"
#include "structure_fem/shape_t10.hpp"
#include "structure_fem/tagged_boundary.hpp"

namespace fsi::fem {

std::vector<int> TetMesh::node_set(const std::string& tag) const {
  return facet_node_set(faces, tag, source, "face");
}

std::vector<BoundaryFace> TetMesh::faces_with_tag(const std::string& tag) const {
  return facets_with_tag(faces, tag, source, "face");
}

void validate_mesh(const TetMesh& mesh) {
  for (std::size_t e = 0; e < mesh.num_elements(); ++e) {
    const std::string where = mesh.source + ": element " + std::to_string(e + 1) + ": ";
    TetNodes X;
    for (std::size_t k = 0; k < 10; ++k) {
      const int node = mesh.elements[e][k];
      if (node < 0 || static_cast<std::size_t>(node) >= mesh.num_nodes())
        throw InputError(where + "node index " + std::to_string(node) + " out of range");
      X[k] = mesh.X[static_cast<std::size_t>(node)];
    }
    if (!(t10_min_jacobian(X) > 0.0))
      throw InputError(where + "det J <= 0 (inverted or degenerate element)");
  }
}

} // namespace fsi::fem
