#include "structure_fem/box_mesher.hpp"

#include <cmath>
#include <string>

#include "fsi/core/error.hpp"
#include "structure_fem/shape_t10.hpp"

namespace fsi::fem {

TetMesh make_box_mesh(const BoxMeshOptions& o) {
  for (int d = 0; d < 3; ++d) {
    if (!(o.size[d] > 0.0) || !std::isfinite(o.size[d]))
      throw InputError("box mesh: size[" + std::to_string(d) + "] = " + std::to_string(o.size[d]) +
                       ": must be > 0");
    if (o.cells[static_cast<std::size_t>(d)] < 1)
      throw InputError("box mesh: cells[" + std::to_string(d) + "] = " +
                       std::to_string(o.cells[static_cast<std::size_t>(d)]) + ": must be >= 1");
  }
  const std::array<int, 3> n{2 * o.cells[0] + 1, 2 * o.cells[1] + 1, 2 * o.cells[2] + 1};
  using Lattice = Eigen::Vector3i; // a node's indices on the half-spacing lattice
  auto id = [&n](const Lattice& p) { return p.x() + n[0] * (p.y() + n[1] * p.z()); };
  TetMesh mesh;
  mesh.source = "box mesh";
  constexpr std::array<const char*, 6> side_tags{"x_min", "x_max", "y_min",
                                                 "y_max", "z_min", "z_max"};
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i)
        mesh.X.push_back(o.origin + Vec3(o.size.x() * i / (n[0] - 1), o.size.y() * j / (n[1] - 1),
                                         o.size.z() * k / (n[2] - 1)));
  // The axis order of each Kuhn tetrahedron; the odd permutations get their vertices 1 and 2
  // swapped for a positive orientation.
  constexpr std::array<std::array<int, 3>, 6> orders{
      {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}}};
  for (int c = 0; c < o.cells[2]; ++c)
    for (int b = 0; b < o.cells[1]; ++b)
      for (int a = 0; a < o.cells[0]; ++a)
        for (std::size_t t = 0; t < orders.size(); ++t) {
          std::array<Lattice, 4> v;
          v[0] = Lattice(2 * a, 2 * b, 2 * c);
          for (std::size_t s = 0; s < 3; ++s) v[s + 1] = v[s] + 2 * Lattice::Unit(orders[t][s]);
          if (t >= 3) std::swap(v[1], v[2]);
          std::array<int, 10> element;
          for (std::size_t s = 0; s < 4; ++s) element[s] = id(v[s]);
          for (std::size_t e = 0; e < t10_edges.size(); ++e) {
            const auto [p, q] = t10_edges[e];
            element[4 + e] =
                id((v[static_cast<std::size_t>(p)] + v[static_cast<std::size_t>(q)]) / 2);
          }
          mesh.elements.push_back(element);
          for (const auto& face : t10_faces) // on a side: the 3 corners share its coordinate
            for (int d = 0; d < 3; ++d)
              for (int side = 0; side < 2; ++side) {
                const int at = side * (n[static_cast<std::size_t>(d)] - 1);
                bool on_side = true;
                for (std::size_t s = 0; s < 3; ++s)
                  on_side = on_side && v[static_cast<std::size_t>(face[s])][d] == at;
                if (!on_side) continue;
                BoundaryFace f{{}, side_tags[static_cast<std::size_t>(2 * d + side)]};
                for (std::size_t s = 0; s < 6; ++s)
                  f.nodes[s] = element[static_cast<std::size_t>(face[s])];
                mesh.faces.push_back(f);
              }
        }
  return mesh;
}

} // namespace fsi::fem
