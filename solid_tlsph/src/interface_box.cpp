// The 3-D solid's coupling interface: the 2-D outline's design on the faces of the box the
// particles fill (geometry.hpp, fill_box). Per tagged face a grid of nodes ON the face: at each
// outer-layer particle's projection and on the face's border lines (the box's edges) at the same
// lattice coordinates, so that the faces meet watertight; two order-1 triangles per grid cell.
// Every node is attached to its nearest particle (clamped ones included: their loads are
// reactions) and moves with it (interface.cpp); a node on a box edge is one node of both faces.
#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include "fsi/core/error.hpp"
#include "particles/lattice.hpp"
#include "solid_tlsph/solid.hpp"

namespace fsi::tlsph {

namespace {
constexpr std::array<const char*, 6> kFaceTags = {"x-", "x+", "y-", "y+", "z-", "z+"};
} // namespace

template <int D>
void BasicTlsphSolid<D>::build_box_interface(const Geometry& geometry) requires(D == 3) {
  if (geometry.box.empty()) return;
  if (geometry.box.size() != 2) throw InputError("tlsph: a box is {lo, hi}");
  const double dp = options_.dp;
  const Vec3 lo = geometry.box[0];
  // The lattice's extent (whole layers from lo, as fill_box seeds them) and the node coordinates
  // along each axis: the faces, and the particles' (i + 1/2) dp in between.
  std::array<long, 3> layers{};
  std::array<std::vector<double>, 3> grid;
  Vec3 hi;
  for (int c = 0; c < 3; ++c) {
    const auto uc = static_cast<std::size_t>(c);
    layers[uc] = particles::lattice_layers(lo[c], geometry.box[1][c], dp);
    if (layers[uc] <= 0) throw InputError("tlsph: the box is thinner than dp");
    hi[c] = lo[c] + static_cast<double>(layers[uc]) * dp;
    grid[uc].push_back(lo[c]);
    for (long i = 0; i < layers[uc]; ++i)
      grid[uc].push_back(lo[c] + (static_cast<double>(i) + 0.5) * dp);
    grid[uc].push_back(hi[c]);
  }
  // The outer layers' particles by lattice index.
  std::map<std::array<long, 3>, std::uint32_t> outer;
  for (std::size_t i = 0; i < size(); ++i) {
    std::array<long, 3> index{};
    bool on_surface = false;
    for (int c = 0; c < 3; ++c) {
      const auto uc = static_cast<std::size_t>(c);
      index[uc] = std::lround((X0_[c][i] - lo[c]) / dp - 0.5);
      on_surface = on_surface || index[uc] == 0 || index[uc] == layers[uc] - 1;
    }
    if (on_surface) outer.emplace(index, static_cast<std::uint32_t>(i));
  }
  auto tagged = [&](std::size_t face) {
    const auto& tags = options_.interface_tags;
    return tags.empty() || std::find(tags.begin(), tags.end(), kFaceTags[face]) != tags.end();
  };
  std::map<std::array<std::size_t, 3>, std::size_t> node_of; // grid index -> node
  auto node = [&](const std::array<std::size_t, 3>& g, const Vec3& outward) {
    const auto [it, added] = node_of.emplace(g, interface_.size());
    if (!added) {
      interface_n0_[it->second] += outward; // a box edge or corner: the faces' normals summed
      return it->second;
    }
    std::array<long, 3> index{};
    Vec3 X;
    for (int c = 0; c < 3; ++c) {
      const auto uc = static_cast<std::size_t>(c);
      X[c] = grid[uc][g[uc]];
      index[uc] = std::clamp(static_cast<long>(g[uc]) - 1, 0L, layers[uc] - 1);
    }
    const auto particle = outer.find(index);
    if (particle == outer.end())
      throw InputError("tlsph: no particle under the box's face at lattice index (" +
                       std::to_string(index[0]) + ", " + std::to_string(index[1]) + ", " +
                       std::to_string(index[2]) + ")");
    interface_.push_back(particle->second);
    interface_n0_.push_back(outward);
    interface_offset_.push_back(X - at(X0_, particle->second));
    interface_mesh_.X0.push_back(X);
    return interface_.size() - 1;
  };
  interface_mesh_.order = 1;
  interface_mesh_.X0.clear();
  interface_mesh_.faces.clear();
  for (std::size_t face = 0; face < 6; ++face) {
    if (!tagged(face)) continue;
    // Normal axis a; in-plane axes b, c with e_b x e_c = e_a.
    const std::size_t a = face / 2, b = (a + 1) % 3, c = (a + 2) % 3;
    const bool high = face % 2 == 1;
    Vec3 outward = Vec3::Zero();
    outward[static_cast<int>(a)] = high ? 1.0 : -1.0;
    std::array<std::size_t, 3> g{};
    g[a] = high ? grid[a].size() - 1 : 0;
    for (std::size_t j = 0; j + 1 < grid[c].size(); ++j)
      for (std::size_t i = 0; i + 1 < grid[b].size(); ++i) {
        std::array<std::size_t, 4> corner{}; // (i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)
        for (std::size_t k = 0; k < 4; ++k) {
          g[b] = i + (k == 1 || k == 2 ? 1 : 0);
          g[c] = j + (k >= 2 ? 1 : 0);
          corner[k] = node(g, outward);
        }
        // Counter-clockwise seen from outside: (x1 - x0) x (x2 - x0) along the outward normal.
        const std::size_t p = corner[0], q = corner[high ? 1 : 3], r = corner[2],
                          s = corner[high ? 3 : 1];
        interface_mesh_.faces.push_back({p, q, r, p, p, p});
        interface_mesh_.faces.push_back({p, r, s, p, p, p});
      }
  }
  for (auto& n : interface_n0_) n.normalize();
  add_particle_nodes();
}

template void BasicTlsphSolid<3>::build_box_interface(const Geometry&);

} // namespace fsi::tlsph
