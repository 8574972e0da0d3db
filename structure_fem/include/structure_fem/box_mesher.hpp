#pragma once
// Structured T10 mesh of a rectangular block (issue 44, first slice: nodes and elements; tagged
// faces and the 3-D Mesh come with the 3-D assembly).
#include <array>
#include <vector>

#include "fsi/core/types.hpp"

namespace fsi::fem {

struct BoxMeshOptions {
  Vec3 origin{0.0, 0.0, 0.0};         ///< the corner with the smallest coordinates [m]
  Vec3 size{1.0, 0.1, 0.1};           ///< extents in x, y, z [m], each > 0
  std::array<int, 3> cells{10, 1, 1}; ///< hexahedral cells along x, y, z, each >= 1
};

/// T10 nodes and elements (node order of shape_t10.hpp).
struct TetMesh {
  std::vector<Vec3> X;
  std::vector<std::array<int, 10>> elements;
};

/// Each cell split into the 6 tetrahedra of the Kuhn (Freudenthal) triangulation round its
/// diagonal from the smallest to the largest corner: the same split in every cell, so the faces
/// match. The nodes are the (2 nx + 1)(2 ny + 1)(2 nz + 1) points of the half-spacing lattice
/// (all of them used: cell and face centres are edge midpoints of the split), numbered x fastest,
/// then y, then z. Every element has a positive volume. Throws InputError for a bad option.
TetMesh make_box_mesh(const BoxMeshOptions& options);

} // namespace fsi::fem
