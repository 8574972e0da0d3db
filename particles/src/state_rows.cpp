#include "particles/state_rows.hpp"

#include <algorithm>
#include <numeric>

namespace fsi::particles {

namespace {
template <class T>
std::vector<T> pick_rows(const std::vector<T>& values, std::size_t n,
                         const std::vector<std::size_t>& pick) {
  const std::size_t width = n ? values.size() / n : 0;
  std::vector<T> out(width * pick.size());
  for (std::size_t j = 0; j < pick.size(); ++j)
    std::copy_n(values.begin() + static_cast<std::ptrdiff_t>(width * pick[j]), width,
                out.begin() + static_cast<std::ptrdiff_t>(width * j));
  return out;
}
} // namespace

void select_rows(const StateArchive& rows, std::size_t n, const std::vector<std::size_t>& pick,
                 StateArchive& out) {
  for (const auto& [key, values] : rows.all_reals()) out.put(key, pick_rows(values, n, pick));
  for (const auto& [key, values] : rows.all_integers()) out.put(key, pick_rows(values, n, pick));
}

template <int D>
void gather_rows(const Decomposition<D>& decomposition, const StateArchive& rows,
                 const std::string& id_key, StateArchive& out) {
  // Ids, then each array, as doubles (integers below 2^53 are exact).
  const std::vector<std::int64_t>& id = rows.integers(id_key);
  std::vector<double> all_ids, all;
  decomposition.gather(std::vector<double>(id.begin(), id.end()), all_ids);
  const std::size_t n = all_ids.size(); // 0 but on process 0
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return all_ids[a] < all_ids[b]; });
  const bool root = decomposition.rank() == 0;
  for (const auto& [key, values] : rows.all_reals()) {
    decomposition.gather(values, all);
    if (root) out.put(key, pick_rows(all, n, order));
  }
  for (const auto& [key, values] : rows.all_integers()) {
    decomposition.gather(std::vector<double>(values.begin(), values.end()), all);
    if (!root) continue;
    const std::vector<double> sorted = pick_rows(all, n, order);
    out.put(key, std::vector<std::int64_t>(sorted.begin(), sorted.end()));
  }
}

template void gather_rows<2>(const Decomposition<2>&, const StateArchive&, const std::string&,
                             StateArchive&);
template void gather_rows<3>(const Decomposition<3>&, const StateArchive&, const std::string&,
                             StateArchive&);

} // namespace fsi::particles
