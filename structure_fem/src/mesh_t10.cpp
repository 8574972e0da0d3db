#include "structure_fem/mesh_t10.hpp"

#include "structure_fem/tagged_boundary.hpp"

namespace fsi::fem {

std::vector<int> TetMesh::node_set(const std::string& tag) const {
  return facet_node_set(faces, tag, source, "face");
}

std::vector<BoundaryFace> TetMesh::faces_with_tag(const std::string& tag) const {
  return facets_with_tag(faces, tag, source, "face");
}

} // namespace fsi::fem
