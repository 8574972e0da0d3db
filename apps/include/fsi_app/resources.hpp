#pragma once
// Up-front resource check: a scene that cannot fit in this machine is refused before the solvers
// allocate anything, with the estimate in the message.
#include "fsi_app/scene.hpp"
#include "fsi_app/scene_reader.hpp"
#include "fsi_app/solver_plugin.hpp"

#include <optional>
#include <vector>

namespace fsi::app {

/// What a scene needs, from the data layout of the solvers (each plug-in's footprint; see
/// docs/reliability.md).
struct MemoryEstimate {
  Footprint fluid;                   ///< count: particles (region area / l0^2)
  std::vector<Footprint> structures; ///< count: elements; 0 for a Gmsh mesh (bounded by file)
  double total() const;
};

MemoryEstimate estimate_memory(const Scene& scene);

/// Memory this process may use, bytes: MemAvailable of /proc/meminfo, lowered to the cgroup
/// limit (v2 memory.max, v1 memory.limit_in_bytes) when one is set. Infinity if unknown.
double available_memory();

/// Throws InputError `FILE:LINE: KEY: ... needs about X GiB, the machine has Y GiB available`
/// (through the scene's sections, so --set overrides are named) when the estimate exceeds
/// `available`, or when a count exceeds the 32-bit indices of the solvers.
void check_resources(const Scene& scene, const std::optional<Section>& fluid,
                     const std::vector<Section>& structures, double available);

} // namespace fsi::app
