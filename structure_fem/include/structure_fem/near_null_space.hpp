#pragma once
// The near null space of an elasticity stiffness on its free dofs: the rigid-body modes (3 in 2-D:
// two translations and the in-plane rotation; 6 in 3-D: three translations, three rotations),
// which smoothed-aggregation multigrid interpolates exactly (Vanek, Mandel & Brezina 1996, sec. 3).
#include <vector>

#include <Eigen/Core>

#include "structure_fem/dof_map.hpp"

namespace fsi::fem {

struct NearNullSpace {
  Eigen::MatrixXd modes; ///< free dofs x modes; rotations about the nodes' centroid
  std::vector<int> node; ///< the node (block) of each free dof, nondecreasing
};

/// The rigid-body modes of the nodes X restricted to the free dofs of `dofs`.
template <int D> NearNullSpace rigid_body_modes(const DofMap& dofs, const std::vector<VecD<D>>& X);

} // namespace fsi::fem
