#include "structure_fem/interface_mesh.hpp"

namespace fsi::fem {

FeInterface interface_of(const Mesh& mesh, const std::vector<std::string>& tags) {
  FeInterface out;
  out.mesh.order = 2;
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
    for (const auto& e : mesh.edges_with_tag(tag)) {
      const std::size_t a = node(e.nodes[0]), m = node(e.nodes[1]), b = node(e.nodes[2]);
      out.mesh.edges.push_back({a, m, b});
    }
  return out;
}

} // namespace fsi::fem
