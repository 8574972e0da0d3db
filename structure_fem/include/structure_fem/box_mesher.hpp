#pragma once
// Structured T10 mesh of a rectangular block with its six sides tagged.
#include <array>
#include <vector>

#include "fsi/core/types.hpp"
#include "structure_fem/mesh_t10.hpp"

namespace fsi::fem {

struct BoxMeshOptions {
  Vec3 origin{0.0, 0.0, 0.0};         ///< the corner with the smallest coordinates [m]
  Vec3 size{1.0, 0.1, 0.1};           ///< extents in x, y, z [m], each > 0
  std::array<int, 3> cells{10, 1, 1}; ///< hexahedral cells along x, y, z, each >= 1
};

/// Each cell split into the 6 tetrahedra of the Kuhn (Freudenthal) triangulation round its
/// diagonal from the smallest to the largest corner: the same split in every cell, so the faces
/// match. The nodes are the (2 nx + 1)(2 ny + 1)(2 nz + 1) points of the half-spacing lattice
/// (all of them used: cell and face centres are edge midpoints of the split), numbered x fastest,
/// then y, then z. Every element has a positive volume. The boundary faces are tagged by the side
/// they lie on: "x_min", "x_max", "y_min", "y_max", "z_min", "z_max". Throws InputError for a
/// bad option.
TetMesh make_box_mesh(const BoxMeshOptions& options);

} // namespace fsi::fem
