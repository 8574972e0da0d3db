#include "structure_fem/dof_map.hpp"

#include "fsi/core/error.hpp"

namespace fsi::fem {

DofMap::DofMap(std::size_t num_nodes, int dim)
    : dim_(dim), free_of_dof_(static_cast<std::size_t>(dim) * num_nodes, 0),
      condition_of_dof_(free_of_dof_.size(), -1) {}

void DofMap::constrain(int node, int c, int i) {
  const std::size_t num_nodes = free_of_dof_.size() / static_cast<std::size_t>(dim_);
  if (node < 0 || static_cast<std::size_t>(node) >= num_nodes)
    throw InputError("clamped: node index " + std::to_string(node) + " out of range (" +
                     std::to_string(num_nodes) + " nodes)");
  const auto dof = static_cast<std::size_t>(dim_ * node + c);
  free_of_dof_[dof] = -1;
  condition_of_dof_[dof] = i;
}

void DofMap::number_free() {
  for (auto& f : free_of_dof_)
    if (f == 0) f = num_free_++;
}

DofMap::DofMap(const Mesh& mesh, const std::vector<DirichletCondition>& conditions)
    : DofMap(mesh.num_nodes(), 2) {
  for (std::size_t i = 0; i < conditions.size(); ++i) {
    const auto& c = conditions[i];
    for (int node : c.tag.empty() ? c.nodes : mesh.node_set(c.tag)) {
      if (c.fix_x) constrain(node, 0, static_cast<int>(i));
      if (c.fix_y) constrain(node, 1, static_cast<int>(i));
    }
  }
  number_free();
}

DofMap::DofMap(const TetMesh& mesh, const std::vector<DirichletCondition3>& conditions)
    : DofMap(mesh.num_nodes(), 3) {
  for (std::size_t i = 0; i < conditions.size(); ++i) {
    const auto& c = conditions[i];
    for (int node : c.tag.empty() ? c.nodes : mesh.node_set(c.tag))
      for (int d = 0; d < 3; ++d)
        if (c.fix[static_cast<std::size_t>(d)]) constrain(node, d, static_cast<int>(i));
  }
  number_free();
}

Vector DofMap::restrict_to_free(const Vector& full) const {
  Vector free(num_free_);
  for (int d = 0; d < num_dofs(); ++d)
    if (free_index(d) >= 0) free[free_index(d)] = full[d];
  return free;
}

void DofMap::add_free(const Vector& free, Vector& full) const {
  for (int d = 0; d < num_dofs(); ++d)
    if (free_index(d) >= 0) full[d] += free[free_index(d)];
}

} // namespace fsi::fem
