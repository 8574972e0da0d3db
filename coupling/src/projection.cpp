#include "coupling/projection.hpp"

#include <algorithm>
#include <cassert>
#include <vector>

#include "fsi/core/parallel.hpp"

namespace fsi::coupling {

namespace {

// Loads per chunk below which one chunk is used; at most max_chunks chunks. Both depend only on
// the input size, so the summation order does not depend on the thread count.
constexpr std::size_t loads_per_chunk = 4096;
constexpr std::size_t max_chunks = 16;

void accumulate(const InterfaceMesh& mesh, std::span<const PointLoad> loads, std::vector<Vec2>& f) {
  for (const PointLoad& p : loads) {
    assert(p.edge < mesh.edges.size());
    assert(p.xi >= -1.0 && p.xi <= 1.0);
    const auto& nodes = mesh.edges[p.edge];
    const auto n = edge_shape_functions(mesh.order, p.xi); // eq. 58: f_L += N_L(x_wall) (-f_wall)
    for (int k = 0; k < 3; ++k) {
      assert(nodes[static_cast<std::size_t>(k)] < f.size());
      f[nodes[static_cast<std::size_t>(k)]] += n[static_cast<std::size_t>(k)] * p.f;
    }
  }
}

} // namespace

void project_point_loads(const InterfaceMesh& mesh, std::span<const PointLoad> loads,
                         InterfaceLoads& out) {
  const std::size_t chunks = std::clamp<std::size_t>(
      (loads.size() + loads_per_chunk - 1) / loads_per_chunk, 1, max_chunks);
  if (chunks == 1) {
    accumulate(mesh, loads, out.f);
    return;
  }
  const std::size_t per = (loads.size() + chunks - 1) / chunks;
  std::vector<std::vector<Vec2>> buffers(chunks, std::vector<Vec2>(out.size(), Vec2::Zero()));
  parallel_for(chunks, [&](std::size_t c) {
    const std::size_t begin = std::min(loads.size(), c * per);
    const std::size_t end = std::min(loads.size(), begin + per);
    accumulate(mesh, loads.subspan(begin, end - begin), buffers[c]);
  });
  for (const auto& b : buffers)
    for (std::size_t i = 0; i < out.size(); ++i) out.f[i] += b[i];
}

} // namespace fsi::coupling
