#include "fluid_emps/particles.hpp"

#include "fsi/core/parallel.hpp"

namespace fsi::emps {

void Particles::resize(std::size_t n) {
  for (auto* a : {&x, &y, &vx, &vy, &p, &pnd}) a->resize(n, 0.0);
  surface.resize(n, 0);
  id.resize(n, 0);
}

namespace {
template <class T, class S>
void permute_one(std::vector<T>& a, const std::vector<std::uint32_t>& order, std::vector<S>& tmp) {
  tmp.resize(a.size());
  parallel_for(a.size(), [&](std::size_t i) { tmp[i] = static_cast<S>(a[order[i]]); });
  parallel_for(a.size(), [&](std::size_t i) { a[i] = static_cast<T>(tmp[i]); });
}
} // namespace

void Particles::permute(const std::vector<std::uint32_t>& order, std::vector<double>& scratch) {
  for (auto* a : {&x, &y, &vx, &vy, &p, &pnd}) permute_one(*a, order, scratch);
  permute_one(surface, order, scratch); // small integers are exact in double
  permute_one(id, order, scratch);
}

std::size_t Particles::compact(const std::vector<std::uint8_t>& keep) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < size(); ++i) {
    if (!keep[i]) continue;
    x[n] = x[i], y[n] = y[i], vx[n] = vx[i], vy[n] = vy[i];
    p[n] = p[i], pnd[n] = pnd[i], surface[n] = surface[i], id[n] = id[i];
    ++n;
  }
  const std::size_t removed = size() - n;
  resize(n);
  return removed;
}

} // namespace fsi::emps
