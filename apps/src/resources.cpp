#include "fsi_app/resources.hpp"

#include "fsi_app/fluid_model.hpp"

#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <numeric>
#include <sstream>

namespace fsi::app {

namespace {

constexpr double kGiB = 1024.0 * 1024.0 * 1024.0;

// Shoelace area of a closed polygon.
double polygon_area(const std::vector<Vec2>& p) {
  double twice = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec2& a = p[i];
    const Vec2& b = p[(i + 1) % p.size()];
    twice += a.x() * b.y() - b.x() * a.y();
  }
  return 0.5 * std::abs(twice);
}

// Bytes per fluid particle, array by array (fluid_emps and geometry_erp headers); `capacity` is
// the neighbour-row length of EmpsFluid.
double bytes_per_particle(double capacity) {
  const double particles = 6 * 8 + 1 + 4;          // Particles SoA: x y vx vy p pnd, surface, id
  const double saved_state = particles;            // EmpsFluid::State for coupling iterations
  const double lattice = 16;                       // fill_lattice positions
  const double neighbours = capacity * 4 + 4 + 16; // index_ rows, count_, x_build_ y_build_
  const double cell_grid = 4 + 4;                  // cell_, order_
  const double wall_hits = 4 + 16 + 64 + 1 + 4 + 16 + 48; // erp::WallHits
  const double wall_forces = 8 + 16 + 64;                 // WallForces
  const double work = 16 + 32 + 1;                        // scratch_, visc_wall_ 2x, keep_
  const double output = 16 + 16 + 8;                      // FluidModel frame buffers
  return particles + saved_state + lattice + neighbours + cell_grid + wall_hits + wall_forces +
         work + output;
}

// A structured T6 rectangle: (2 nx + 1)(2 ny + 1) nodes, 2 nx ny elements. Per degree of
// freedom the sparse M, K and K_eff hold about 26 entries per row (12 B each in CSR), the
// Cholesky factor about 8 times the entries of K (2D nested dissection fill, an assumption), and
// about 16 state and work vectors; per element the 144 assembly triplets (16 B each).
double structure_bytes(double elements_x, double elements_y) {
  const double nodes = (2 * elements_x + 1) * (2 * elements_y + 1);
  const double elements = 2 * elements_x * elements_y;
  const double dofs = 2 * nodes;
  const double row_entries = 26;
  const double per_dof = 3 * row_entries * 12 + 8 * row_entries * 12 + 16 * 8;
  const double per_element = 144 * 16 + 6 * 4 + 8;
  const double per_node = 16 + 16 + 8; // X, positions, node_label
  return dofs * per_dof + elements * per_element + nodes * per_node;
}

std::string gib(double bytes) {
  std::ostringstream out;
  out.precision(bytes < 10 * kGiB ? 2 : 3);
  out << bytes / kGiB;
  return out.str();
}

std::string count(double n) {
  std::ostringstream out;
  out.precision(3);
  out << n;
  return out.str();
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
  return std::accumulate(structure_bytes.begin(), structure_bytes.end(), fluid_bytes);
}

MemoryEstimate estimate_memory(const Scene& scene) {
  MemoryEstimate e;
  if (scene.fluid) {
    const FluidSpec& f = *scene.fluid;
    for (const auto& region : f.regions) e.particles += polygon_area(region) / (f.l0 * f.l0);
    const emps::FluidOptions o = fluid_options(scene);
    const double reach = (1.0 + o.skin) * o.re_over_l0; // as EmpsFluid sizes its rows
    const double capacity = std::ceil(2.0 * M_PI * reach * reach) + 16;
    const double h = o.r_e() * (1.0 + o.skin); // CellGrid cell size
    const Vec2 span = o.domain_max - o.domain_min;
    e.cells = (std::ceil(span.x() / h) + 3) * (std::ceil(span.y() / h) + 3);
    e.fluid_bytes = e.particles * bytes_per_particle(capacity) + e.cells * 4;
  }
  for (const auto& st : scene.structures) {
    const bool rectangle = st.mesh.kind == "rectangle";
    const double nx = st.mesh.elements_x, ny = st.mesh.elements_y;
    e.structure_elements.push_back(rectangle ? 2 * nx * ny : 0.0);
    e.structure_bytes.push_back(rectangle ? structure_bytes(nx, ny) : 0.0);
  }
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
  if (e.total() > available) {
    // Blame the largest part; the message gives the whole scene's estimate.
    std::size_t largest = 0;
    for (std::size_t i = 1; i < e.structure_bytes.size(); ++i)
      if (e.structure_bytes[i] > e.structure_bytes[largest]) largest = i;
    const bool structure_larger =
        !e.structure_bytes.empty() && e.structure_bytes[largest] > e.fluid_bytes;
    if (fluid && !structure_larger) {
      const bool grid_larger = 4 * e.cells > e.fluid_bytes / 2 && fluid->has("domain");
      fluid->fail(grid_larger ? "domain" : "l0", count(e.particles) +
                                                     " particles (fluid region area / l0^2) and " +
                                                     count(e.cells) + " cells" + needs);
    }
    structures[largest].fail("mesh", count(e.structure_elements[largest]) +
                                         " T6 elements (2 elements_x elements_y)" + needs);
  }
  // Particle ids and neighbour indices are 32-bit, cell indices and sparse-matrix indices int.
  const double int_max = std::numeric_limits<int>::max();
  if (fluid && e.particles > std::numeric_limits<std::uint32_t>::max())
    fluid->fail("l0", count(e.particles) + " particles: more than the 2^32 particle indices hold");
  if (fluid && e.cells > int_max)
    fluid->fail("l0", count(e.cells) + " cells over the fluid domain: more than 2^31");
  for (std::size_t i = 0; i < structures.size(); ++i)
    if (e.structure_elements[i] * 4 * 26 > int_max) // 2 dofs x 2 nodes per element, 26 per row
      structures[i].fail("mesh", count(e.structure_elements[i]) +
                                     " T6 elements: the sparse matrices would exceed 2^31 entries");
}

} // namespace fsi::app
