#pragma once
// The coupling interface of an FE mesh, for any fluid to build its boundary from
// (core/interface_mesh.hpp): a T6 mesh's tagged boundary edges as order-2 interface edges
// (corner, mid, corner; the solid on the left of corner -> corner, the order of a T6 element's
// own edges), a T10 mesh's tagged boundary faces as order-2 interface faces (corners, then
// mid-sides, Gmsh's 6-node triangle; (x1 - x0) x (x2 - x0) out of the solid, into the fluid).
#include "fsi/core/interface_mesh.hpp"
#include "structure_fem/mesh.hpp"
#include "structure_fem/mesh_t10.hpp"

#include <string>
#include <vector>

namespace fsi::fem {

template <int D> struct BasicFeInterface {
  BasicInterfaceMesh<D> mesh; ///< interface nodes in order of first appearance on the elements
  std::vector<int> fe_node;   ///< FE node of interface node k (NCR, eq. 50)
};
using FeInterface = BasicFeInterface<2>;
using FeInterface3 = BasicFeInterface<3>;

/// The edges of `mesh` tagged with any of `tags`, in tag order and then mesh order. Throws
/// InputError if a tag is on no edge.
FeInterface interface_of(const Mesh& mesh, const std::vector<std::string>& tags);

/// The faces of `mesh` tagged with any of `tags`, in tag order and then mesh order. Throws
/// InputError if a tag is on no face.
FeInterface3 interface_of(const TetMesh& mesh, const std::vector<std::string>& tags);

} // namespace fsi::fem
