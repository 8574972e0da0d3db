#pragma once
// Duplicate nodes of a mesh (private to structure_fem): the T6 mesh's validate_mesh and the T10
// Gmsh reader.
#include <algorithm>
#include <cstddef>
#include <numeric>
#include <optional>
#include <utility>
#include <vector>

namespace fsi::fem {

/// A pair of nodes a < b within `tol` of each other (the nodes sorted by x, each compared with
/// those whose x is within tol), or none.
template <class Point>
std::optional<std::pair<std::size_t, std::size_t>> duplicate_nodes(const std::vector<Point>& X,
                                                                   double tol) {
  std::vector<std::size_t> order(X.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](auto a, auto b) { return X[a].x() < X[b].x(); });
  for (std::size_t i = 0; i < order.size(); ++i)
    for (std::size_t j = i + 1; j < order.size() && X[order[j]].x() - X[order[i]].x() <= tol; ++j)
      if ((X[order[j]] - X[order[i]]).norm() <= tol) return std::minmax(order[i], order[j]);
  return std::nullopt;
}

} // namespace fsi::fem
