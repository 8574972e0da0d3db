#include "structure_fem/aggregation.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include <Eigen/QR>

namespace fsi::fem {

namespace {

/// First dof of each block, and the block count at the end: node is nondecreasing.
std::vector<int> block_starts(const std::vector<int>& node) {
  std::vector<int> start;
  for (std::size_t i = 0; i < node.size(); ++i)
    if (i == 0 || node[i] != node[i - 1]) start.push_back(static_cast<int>(i));
  start.push_back(static_cast<int>(node.size()));
  return start;
}

} // namespace

StrengthGraph strength_graph(const SparseMatrix& A, const std::vector<int>& node, double theta) {
  const std::vector<int> start = block_starts(node);
  const auto blocks = static_cast<int>(start.size()) - 1;
  std::vector<int> block_of_dof(node.size());
  for (int I = 0; I < blocks; ++I)
    std::fill(block_of_dof.begin() + start[I], block_of_dof.begin() + start[I + 1], I);
  // Block norms column by column of blocks: ||A_IJ||^2 accumulated in `sum`.
  std::vector<int> offsets{0}, rows;
  std::vector<double> norms, sum(static_cast<std::size_t>(blocks), 0.0), diagonal(sum);
  std::vector<int> touched, column_of(static_cast<std::size_t>(blocks), -1);
  for (int J = 0; J < blocks; ++J) {
    for (int j = start[J]; j < start[J + 1]; ++j)
      for (SparseMatrix::InnerIterator it(A, j); it; ++it) {
        const int I = block_of_dof[static_cast<std::size_t>(it.index())];
        if (column_of[I] != J) column_of[I] = J, touched.push_back(I);
        sum[I] += it.value() * it.value();
      }
    for (const int I : touched) {
      rows.push_back(I);
      norms.push_back(std::sqrt(sum[I]));
      if (I == J) diagonal[J] = norms.back();
      sum[I] = 0.0;
    }
    touched.clear();
    offsets.push_back(static_cast<int>(rows.size()));
  }
  StrengthGraph g{{0}, {}, {}};
  for (int J = 0; J < blocks; ++J) {
    for (int k = offsets[J]; k < offsets[J + 1]; ++k) {
      const int I = rows[k];
      const double s = norms[k] / std::sqrt(diagonal[I] * diagonal[J]);
      if (I != J && s > theta) g.neighbours.push_back(I), g.strength.push_back(s);
    }
    g.offsets.push_back(static_cast<int>(g.neighbours.size()));
  }
  return g;
}

int aggregate(const StrengthGraph& g, std::vector<int>& agg) {
  const auto nodes = static_cast<int>(g.offsets.size()) - 1;
  agg.assign(static_cast<std::size_t>(nodes), -1);
  int count = 0;
  // Pass 1: a node whose strong neighbours are all free starts an aggregate of them all.
  for (int i = 0; i < nodes; ++i) {
    if (agg[i] >= 0) continue;
    bool free = true;
    for (int k = g.offsets[i]; k < g.offsets[i + 1] && free; ++k) free = agg[g.neighbours[k]] < 0;
    if (!free) continue;
    agg[i] = count;
    for (int k = g.offsets[i]; k < g.offsets[i + 1]; ++k) agg[g.neighbours[k]] = count;
    ++count;
  }
  // Pass 2: the rest join the pass-1 aggregate they are most strongly coupled to.
  const std::vector<int> first = agg;
  for (int i = 0; i < nodes; ++i) {
    if (first[i] >= 0) continue;
    double best = 0.0;
    for (int k = g.offsets[i]; k < g.offsets[i + 1]; ++k)
      if (first[g.neighbours[k]] >= 0 && g.strength[k] > best)
        best = g.strength[k], agg[i] = first[g.neighbours[k]];
  }
  // Pass 3: what is left forms aggregates with its still free strong neighbours.
  for (int i = 0; i < nodes; ++i) {
    if (agg[i] >= 0) continue;
    agg[i] = count;
    for (int k = g.offsets[i]; k < g.offsets[i + 1]; ++k)
      if (agg[g.neighbours[k]] < 0) agg[g.neighbours[k]] = count;
    ++count;
  }
  return count;
}

SparseMatrix tentative_prolongator(const NearNullSpace& fine, const std::vector<int>& agg,
                                   int aggregates, NearNullSpace& coarse) {
  const auto n = static_cast<Eigen::Index>(fine.node.size());
  const Eigen::Index modes = fine.modes.cols();
  // The fine dofs of each aggregate, in dof order (counting sort by aggregate).
  std::vector<int> first(static_cast<std::size_t>(aggregates) + 1, 0), dofs(fine.node.size());
  const std::vector<int> starts = block_starts(fine.node);
  std::vector<int> agg_of_dof(fine.node.size());
  for (std::size_t I = 0; I + 1 < starts.size(); ++I)
    for (int i = starts[I]; i < starts[I + 1]; ++i) agg_of_dof[i] = agg[I];
  for (const int a : agg_of_dof) ++first[a + 1];
  for (int a = 0; a < aggregates; ++a) first[a + 1] += first[a];
  std::vector<int> next(first.begin(), first.end() - 1);
  for (Eigen::Index i = 0; i < n; ++i) dofs[next[agg_of_dof[i]]++] = static_cast<int>(i);

  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<std::size_t>(n * modes));
  std::vector<Eigen::MatrixXd> blocks; // R P^T of each aggregate
  coarse.node.clear();
  int columns = 0;
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr;
  for (int a = 0; a < aggregates; ++a) {
    const int m = first[a + 1] - first[a];
    Eigen::MatrixXd B(m, modes);
    for (int r = 0; r < m; ++r) B.row(r) = fine.modes.row(dofs[first[a] + r]);
    qr.setThreshold(1e-10);
    qr.compute(B);
    const auto rank = qr.rank();
    assert(rank > 0);
    const Eigen::MatrixXd Q = qr.householderQ() * Eigen::MatrixXd::Identity(m, rank);
    for (int r = 0; r < m; ++r)
      for (Eigen::Index c = 0; c < rank; ++c)
        entries.emplace_back(dofs[first[a] + r], columns + static_cast<int>(c), Q(r, c));
    Eigen::MatrixXd R = qr.matrixR().topRows(rank).triangularView<Eigen::Upper>();
    blocks.push_back(R * qr.colsPermutation().transpose());
    coarse.node.insert(coarse.node.end(), static_cast<std::size_t>(rank), a);
    columns += static_cast<int>(rank);
  }
  coarse.modes.resize(columns, modes);
  for (int a = 0, row = 0; a < aggregates; ++a) {
    coarse.modes.middleRows(row, blocks[a].rows()) = blocks[a];
    row += static_cast<int>(blocks[a].rows());
  }
  SparseMatrix P0(n, columns);
  P0.setFromTriplets(entries.begin(), entries.end());
  return P0;
}

} // namespace fsi::fem
