// Gmsh .msh import of a T10 mesh: the 10-node tetrahedra checked one by one (the volume's sign
// and size, det J of the curved map: the checks validate_mesh makes of T6 elements), unused and
// duplicate nodes, and the 6-node triangles of physical surfaces turned into faces oriented out of
// the tetrahedron they bound.
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <string>
#include <utility>

#include <Eigen/Geometry>

#include "duplicate_nodes.hpp"
#include "fsi/core/error.hpp"
#include "gmsh_sections.hpp"
#include "structure_fem/element_t10.hpp"
#include "structure_fem/gmsh_reader.hpp"
#include "structure_fem/shape_t10.hpp"

namespace fsi::fem {

using gmsh::Parsed;
using gmsh::RawElement;

namespace {

/// Refuses a tetrahedron of zero or negative volume (corners 0, 1, 2 clockwise seen from corner
/// 3) or with det J <= 0 inside; `diag` is the mesh's bounding-box diagonal.
void check_tetrahedron(const Parsed& p, const RawElement& el, const TetNodes& X, double diag) {
  const std::string where = p.at(el.line) + "element " + std::to_string(el.tag) + ": ";
  const double volume = (X[1] - X[0]).cross(X[2] - X[0]).dot(X[3] - X[0]) / 6.0;
  if (!std::isfinite(volume))
    throw InputError(where + "volume is not a finite number (coordinates too large)");
  if (std::abs(volume) <= 1e-12 * diag * diag * diag)
    throw InputError(where + "zero-volume element");
  if (volume < 0.0)
    throw InputError(where + "inverted element (negative volume: corners 0, 1, 2 clockwise seen "
                             "from corner 3)");
  if (t10_min_jacobian(X) <= 0.0)
    throw InputError(where + "inverted element (det J <= 0 inside; mid-node too far from its "
                             "edge midpoint)");
}

/// The diagonal of the nodes' bounding box (no overflow at 1e160 m).
double diagonal(const std::vector<Vec3>& X) {
  Vec3 lo = X.empty() ? Vec3::Zero() : X[0], hi = lo;
  for (const auto& x : X) lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
  return std::hypot(hi.x() - lo.x(), hi.y() - lo.y(), hi.z() - lo.z());
}

/// The tetrahedra of the file, each checked; throws if there are none.
void read_tetrahedra(const Parsed& p, TetMesh& mesh, double diag) {
  bool triangles = false;
  for (const auto& el : p.elements) {
    triangles = triangles || el.type == p.boundary_type();
    if (el.type != p.domain_type()) continue;
    std::array<int, 10> nodes{};
    TetNodes X;
    for (std::size_t k = 0; k < nodes.size(); ++k) {
      nodes[k] = el.nodes[k];
      X[k] = p.X[static_cast<std::size_t>(nodes[k])];
    }
    check_tetrahedron(p, el, X, diag);
    mesh.elements.push_back(nodes);
  }
  if (mesh.elements.empty() && triangles)
    throw InputError(p.path + ": a 2-D mesh (6-node triangles, no 10-node tetrahedra): read it "
                              "as a 2-D solid, or mesh the volume with gmsh -3 -order 2");
  if (mesh.elements.empty())
    throw InputError(p.path + ": the mesh has no T10 elements (10-node tetrahedra, type 11)");
}

/// Refuses a node no tetrahedron uses (a free, massless dof) and two nodes at the same place
/// (within 1e-10 of the diagonal: the solid would be cut there), as validate_mesh does for T6.
void check_nodes(const Parsed& p, const TetMesh& mesh, double diag) {
  auto node = [&](std::size_t k) {
    return (k < p.node_line.size() ? p.at(p.node_line[k]) : p.path + ": ") + "node " +
           std::to_string(p.node_label[k]);
  };
  std::vector<char> used(mesh.num_nodes(), 0);
  for (const auto& el : mesh.elements)
    for (int k : el) used[static_cast<std::size_t>(k)] = 1;
  for (std::size_t k = 0; k < used.size(); ++k)
    if (!used[k]) throw InputError(node(k) + ": unused node (belongs to no element)");
  if (const auto pair = duplicate_nodes(mesh.X, 1e-10 * diag))
    throw InputError(node(pair->second) + ": duplicate node (same coordinates as node " +
                     std::to_string(p.node_label[pair->first]) + ")");
}

/// The triangles of physical surfaces as faces of the tetrahedra, oriented out of them.
void read_faces(const Parsed& p, TetMesh& mesh) {
  // Each tetrahedron face by its sorted nodes: the face oriented out of the (last) tetrahedron
  // that has it, and how many have it.
  std::map<std::array<int, 6>, std::pair<std::array<int, 6>, int>> faces;
  for (const auto& el : mesh.elements)
    for (const auto& face : t10_faces) {
      std::array<int, 6> nodes{};
      for (std::size_t s = 0; s < nodes.size(); ++s)
        nodes[s] = el[static_cast<std::size_t>(face[s])];
      auto key = nodes;
      std::sort(key.begin(), key.end());
      auto& [oriented, count] = faces[key];
      oriented = nodes;
      ++count;
    }
  for (const auto& raw : p.elements) {
    const std::vector<long>* physicals = p.physicals(raw);
    if (raw.type != p.boundary_type() || !physicals) continue;
    std::array<int, 6> key{};
    std::copy(raw.nodes.begin(), raw.nodes.end(), key.begin());
    std::sort(key.begin(), key.end());
    const auto it = faces.find(key);
    const std::string triangle = p.at(raw.line) + "triangle element " + std::to_string(raw.tag);
    if (it == faces.end()) throw InputError(triangle + " is not a face of any tetrahedron");
    if (it->second.second > 1)
      throw InputError(triangle + " is inside the solid (a face of two tetrahedra), not on its "
                                  "boundary");
    for (long phys : *physicals) mesh.faces.push_back({it->second.first, p.boundary_name(phys)});
  }
}

} // namespace

TetMesh read_gmsh_t10(const std::string& path, const std::vector<std::string>& required_groups) {
  auto in = gmsh::open_mesh_file(path);
  return read_gmsh_t10(in, path, required_groups);
}

TetMesh read_gmsh_t10(std::istream& in, const std::string& path,
                      const std::vector<std::string>& required_groups) {
  const Parsed p = gmsh::parse(in, path, 3, required_groups);
  TetMesh mesh;
  mesh.source = path;
  mesh.X = p.X;
  const double diag = diagonal(p.X);
  read_tetrahedra(p, mesh, diag);
  check_nodes(p, mesh, diag);
  read_faces(p, mesh);
  return mesh;
}

} // namespace fsi::fem
