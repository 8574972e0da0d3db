#pragma once
// Query records (wall hits, convex pieces) are rewritten by each query wherever they are read;
// a point far from every wall leaves most of its entries unwritten, so their pages are never
// touched. Grown with std::vector::resize, the old entries would be copied into the new block,
// making every page of it resident (about 0.4 GiB a rank on the 1M-particle 3-D case at the first
// query after the ghosts arrive: docs/performance.md "Set-up memory per rank").
#include <cstddef>
#include <vector>

namespace fsi {

/// v sized n; growing past its capacity, a new block without the old entries (none is kept).
template <class T, class A> void fresh_resize(std::vector<T, A>& v, std::size_t n) {
  if (n > v.capacity()) std::vector<T, A>().swap(v);
  v.resize(n);
}

} // namespace fsi
