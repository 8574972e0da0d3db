#pragma once
// The global sparse pattern on the free dofs of a mesh of N-dof elements (T6: 12, T10: 30), and
// the scatter of element matrices into it. Built once per mesh; the scatter runs serially in
// element order, so the sums do not depend on the thread count.
#include <algorithm>
#include <vector>

#include "structure_fem/types.hpp"

namespace fsi::fem {

template <int N> class ElementScatter {
public:
  using ElementMatrix = Eigen::Matrix<double, N, N>;

  ElementScatter() = default;
  /// free_index(e, i): the free index of dof i of element e, or -1 if it is constrained.
  template <class FreeIndex>
  ElementScatter(std::size_t num_elements, int num_free, FreeIndex&& free_index)
      : slot_(num_elements * N * N, -1) {
    std::vector<Eigen::Triplet<double>> triplets;
    triplets.reserve(num_elements * N * N);
    for (std::size_t e = 0; e < num_elements; ++e)
      for (int j = 0; j < N; ++j)
        for (int i = 0; i < N; ++i)
          if (free_index(e, i) >= 0 && free_index(e, j) >= 0)
            triplets.emplace_back(free_index(e, i), free_index(e, j), 0.0);
    pattern_.resize(num_free, num_free);
    pattern_.setFromTriplets(triplets.begin(), triplets.end());
    pattern_.makeCompressed();
    // slot_[N^2 e + i + N j]: position of (row i, column j) of element e in the value array.
    const int* outer = pattern_.outerIndexPtr();
    const int* inner = pattern_.innerIndexPtr();
    for (std::size_t e = 0; e < num_elements; ++e)
      for (int j = 0; j < N; ++j)
        for (int i = 0; i < N; ++i) {
          const int r = free_index(e, i), c = free_index(e, j);
          if (r < 0 || c < 0) continue;
          const int* pos = std::lower_bound(inner + outer[c], inner + outer[c + 1], r);
          slot_[static_cast<std::size_t>(N * N) * e + static_cast<std::size_t>(i + N * j)] =
              static_cast<int>(pos - inner);
        }
  }

  /// Sparsity pattern on the free dofs (all values zero), full symmetric storage.
  const SparseMatrix& pattern() const { return pattern_; }

  /// A's values (A with pattern()'s structure) = sum over elements of their free-free blocks.
  void scatter(const std::vector<ElementMatrix>& Ke, SparseMatrix& A) const {
    double* values = A.valuePtr();
    std::fill(values, values + A.nonZeros(), 0.0);
    for (std::size_t e = 0; e < Ke.size(); ++e) {
      const int* slot = &slot_[static_cast<std::size_t>(N * N) * e];
      const double* k = Ke[e].data(); // column-major, k[i + N j]
      for (int ij = 0; ij < N * N; ++ij)
        if (slot[ij] >= 0) values[slot[ij]] += k[ij];
    }
  }

private:
  SparseMatrix pattern_;
  std::vector<int> slot_; ///< per element, N^2 value positions in pattern_ (-1: constrained)
};

} // namespace fsi::fem
