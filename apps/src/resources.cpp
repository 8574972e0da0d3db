#include "fsi_app/resources.hpp"

#include "fsi/core/format.hpp"
#include "fsi_app/solver_plugin.hpp"

#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <numeric>
#include <sstream>

namespace fsi::app {

namespace {

constexpr double kGiB = 1024.0 * 1024.0 * 1024.0;

std::string gib(double bytes) {
  return significant(bytes / kGiB, bytes < 10 * kGiB ? 2 : 3);
}

// The value of `key` in a /proc/meminfo-style file, in bytes (kB lines), or infinity.
double meminfo_bytes(const std::string& key) {
  std::ifstream in("/proc/meminfo");
  for (std::string name; in >> name;) {
    double kb = 0.0;
    in >> kb;
    if (name == key + ":") return kb * 1024.0;
    in.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
  }
  return std::numeric_limits<double>::infinity();
}

// A cgroup limit file: a byte count, or "max" / absent for no limit.
double cgroup_limit(const char* path) {
  std::ifstream in(path);
  double bytes = 0.0;
  if (in >> bytes && bytes > 0) return bytes;
  return std::numeric_limits<double>::infinity();
}

} // namespace

double MemoryEstimate::total() const {
  double sum = fluid.bytes;
  for (const auto& s : structures) sum += s.bytes;
  return sum;
}

MemoryEstimate estimate_memory(const Scene& scene) {
  MemoryEstimate e;
  if (scene.fluid) e.fluid = find_fluid_plugin(scene.fluid->type)->footprint(scene);
  for (std::size_t i = 0; i < scene.structures.size(); ++i)
    e.structures.push_back(find_structure_plugin(scene.structures[i].type)->footprint(scene, i));
  return e;
}

double available_memory() {
  double bytes = meminfo_bytes("MemAvailable");
  bytes = std::min(bytes, cgroup_limit("/sys/fs/cgroup/memory.max"));
  bytes = std::min(bytes, cgroup_limit("/sys/fs/cgroup/memory/memory.limit_in_bytes"));
  return bytes;
}

void check_resources(const Scene& scene, const std::optional<Section>& fluid,
                     const std::vector<Section>& structures, double available) {
  const MemoryEstimate e = estimate_memory(scene);
  const std::string needs = ": the scene needs about " + gib(e.total()) + " GiB, the machine has " +
                            gib(available) + " GiB available";
  if (e.total() > available) { // blame the largest part; the message gives the whole estimate
    std::size_t largest = 0;
    for (std::size_t i = 1; i < e.structures.size(); ++i)
      if (e.structures[i].bytes > e.structures[largest].bytes) largest = i;
    if (fluid && (e.structures.empty() || e.structures[largest].bytes <= e.fluid.bytes))
      fluid->fail(e.fluid.key, e.fluid.counts + needs);
    structures[largest].fail(e.structures[largest].key, e.structures[largest].counts + needs);
  }
  // Counts beyond the solvers' index types (32-bit particle ids, int sparse indices, ...).
  if (fluid)
    for (const auto& [key, what] : e.fluid.overflows) fluid->fail(key, what);
  for (std::size_t i = 0; i < structures.size(); ++i)
    for (const auto& [key, what] : e.structures[i].overflows) structures[i].fail(key, what);
}

} // namespace fsi::app
