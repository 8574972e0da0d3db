#pragma once
// The coupling interface of a T6 mesh: its boundary edges with the given tags as order-2
// interface edges (corner, mid, corner; the solid on the left of corner -> corner, the order of a
// T6 element's own edges), for any fluid to build its boundary from (core/interface_mesh.hpp).
#include "fsi/core/interface_mesh.hpp"
#include "structure_fem/mesh.hpp"

#include <string>
#include <vector>

namespace fsi::fem {

struct FeInterface {
  InterfaceMesh mesh;       ///< interface nodes in order of first appearance along the edges
  std::vector<int> fe_node; ///< FE node of interface node k (NCR, eq. 50)
};

/// The edges of `mesh` tagged with any of `tags`, in tag order and then mesh order.
FeInterface interface_of(const Mesh& mesh, const std::vector<std::string>& tags);

} // namespace fsi::fem
