#include "coupling/projection.hpp"

#include <algorithm>
#include <cassert>
#include <type_traits>
#include <vector>

#include "fsi/core/parallel.hpp"

namespace fsi::coupling {

namespace {

// Loads per chunk below which one chunk is used; at most max_chunks chunks. Both depend only on
// the input size, so the summation order does not depend on the thread count.
constexpr std::size_t loads_per_chunk = 4096;
constexpr std::size_t max_chunks = 16;

template <int D>
void accumulate(const BasicInterfaceMesh<D>& mesh, std::span<const BasicPointLoad<D>> loads,
                std::vector<VecD<D>>& f) {
  for (const BasicPointLoad<D>& p : loads) {
    assert(p.element() < mesh.elements().size());
    assert(in_parent_element(p.parent()));
    const auto& nodes = mesh.elements()[p.element()];
    // eq. 58: f_L += N_L(x_wall) (-f_wall)
    const auto n = element_shape_functions(mesh, p.parent());
    for (std::size_t k = 0; k < n.size(); ++k) {
      assert(nodes[k] < f.size());
      f[nodes[k]] += n[k] * p.f;
    }
  }
}

} // namespace

template <int D>
void project_point_loads(const BasicInterfaceMesh<D>& mesh,
                         std::type_identity_t<std::span<const BasicPointLoad<D>>> loads,
                         BasicInterfaceLoads<D>& out) {
  const std::size_t chunks = std::clamp<std::size_t>(
      (loads.size() + loads_per_chunk - 1) / loads_per_chunk, 1, max_chunks);
  if (chunks == 1) {
    accumulate(mesh, loads, out.f);
    return;
  }
  const std::size_t per = (loads.size() + chunks - 1) / chunks;
  std::vector<std::vector<VecD<D>>> buffers(chunks,
                                            std::vector<VecD<D>>(out.size(), VecD<D>::Zero()));
  parallel_for(chunks, [&](std::size_t c) {
    const std::size_t begin = std::min(loads.size(), c * per);
    const std::size_t end = std::min(loads.size(), begin + per);
    accumulate(mesh, loads.subspan(begin, end - begin), buffers[c]);
  });
  for (const auto& b : buffers)
    for (std::size_t i = 0; i < out.size(); ++i) out.f[i] += b[i];
}

template void project_point_loads(const InterfaceMesh&, std::span<const PointLoad>,
                                  InterfaceLoads&);
template void project_point_loads(const InterfaceMesh3&, std::span<const PointLoad3>,
                                  InterfaceLoads3&);

} // namespace fsi::coupling
