#include "structure_fem/interface_mesh.hpp"

namespace fsi::fem {

namespace {

/// The facets (edges or faces) `tagged(tag)` returns for each of `tags`, each facet's nodes in
/// its own order; interface nodes numbered in order of first appearance.
template <int D, class FeMesh, class Tagged>
BasicFeInterface<D> tagged_interface(const FeMesh& mesh, const std::vector<std::string>& tags,
                                     const Tagged& tagged) {
  BasicFeInterface<D> out;
  out.mesh.order = 2;
  auto& elements = [&out]() -> auto& {
    if constexpr (D == 2)
      return out.mesh.edges;
    else
      return out.mesh.faces;
  }
  ();
  std::vector<int> interface_node(mesh.num_nodes(), -1); // FE node -> interface node
  const auto node = [&](int K) {
    int& k = interface_node[static_cast<std::size_t>(K)];
    if (k < 0) {
      k = static_cast<int>(out.fe_node.size());
      out.fe_node.push_back(K);
      out.mesh.X0.push_back(mesh.X[static_cast<std::size_t>(K)]);
    }
    return static_cast<std::size_t>(k);
  };
  for (const auto& tag : tags)
    for (const auto& f : tagged(tag)) {
      typename std::decay_t<decltype(elements)>::value_type element;
      for (std::size_t i = 0; i < element.size(); ++i) element[i] = node(f.nodes[i]);
      elements.push_back(element);
    }
  return out;
}

} // namespace

FeInterface interface_of(const Mesh& mesh, const std::vector<std::string>& tags) {
  return tagged_interface<2>(mesh, tags,
                             [&mesh](const std::string& tag) { return mesh.edges_with_tag(tag); });
}

FeInterface3 interface_of(const TetMesh& mesh, const std::vector<std::string>& tags) {
  return tagged_interface<3>(mesh, tags,
                             [&mesh](const std::string& tag) { return mesh.faces_with_tag(tag); });
}

} // namespace fsi::fem
