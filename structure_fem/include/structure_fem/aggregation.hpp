#pragma once
// The set-up pieces of smoothed aggregation (Vanek, Mandel & Brezina 1996, "Algebraic multigrid
// by smoothed aggregation for second and fourth order elliptic problems", sec. 3-4): the
// node-block strength graph, the aggregates and the tentative prolongator from the near null
// space.
#include <vector>

#include "structure_fem/near_null_space.hpp"
#include "structure_fem/types.hpp"

namespace fsi::fem {

/// Strong neighbours of each node (block) in compressed rows: node I's are
/// neighbours[offsets[I] .. offsets[I + 1]). I and J != I are strongly coupled when
/// ||A_IJ|| > theta sqrt(||A_II|| ||A_JJ||), Frobenius norms of the node blocks (eq. 3.1 of
/// Vanek et al. applied to blocks). `node` is nondecreasing: each block's dofs are contiguous.
struct StrengthGraph {
  std::vector<int> offsets, neighbours;
  std::vector<double> strength; ///< ||A_IJ|| / sqrt(||A_II|| ||A_JJ||) of each neighbour
};
StrengthGraph strength_graph(const SparseMatrix& A, const std::vector<int>& node, double theta);

/// The aggregate of every node by the three passes of Vanek et al. (sec. 4.1): whole strong
/// neighbourhoods of nodes not yet touched, then the rest joined to their most strongly coupled
/// aggregate, then what remains grouped with its free strong neighbours. Returns the count.
int aggregate(const StrengthGraph& graph, std::vector<int>& aggregate_of_node);

/// The tentative prolongator (Vanek et al., eq. 4.2): on each aggregate, the rows of the near
/// null space B orthonormalised by a column-pivoted QR, B_agg P = Q R; the aggregate's coarse
/// dofs are Q's rank(B_agg) columns, and the coarse near null space is R P^T (so P0 B_c = B).
SparseMatrix tentative_prolongator(const NearNullSpace& fine,
                                   const std::vector<int>& aggregate_of_node, int aggregates,
                                   NearNullSpace& coarse);

} // namespace fsi::fem
