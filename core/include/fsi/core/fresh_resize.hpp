#pragma once
// Query records (wall hits, convex pieces) are rewritten by each query wherever they are read,
// so their old entries need not survive a growth. Grown past its capacity by std::vector::resize,
// a record keeps its old block alive while copying it into the new one: on the 1M-particle 3-D
// case the first query after the ghosts arrive held about 0.4 GiB a rank more at np = 2 (the
// mechanism inferred, the net effect measured: docs/performance.md "Set-up memory per rank").
#include <cstddef>
#include <vector>

namespace fsi {

/// v sized n; growing past its capacity, a new block without the old entries (none is kept).
template <class T, class A> void fresh_resize(std::vector<T, A>& v, std::size_t n) {
  if (n > v.capacity()) std::vector<T, A>().swap(v);
  v.resize(n);
}

} // namespace fsi
