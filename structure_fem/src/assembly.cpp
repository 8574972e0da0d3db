#include "structure_fem/assembly.hpp"

#include <sstream>

#include "fsi/core/parallel.hpp"

namespace fsi::fem {

template <class Family>
BasicAssembler<Family>::BasicAssembler(const typename Family::Mesh& mesh,
                                       const typename Family::Material& material,
                                       const DofMap& dofs)
    : mesh_(mesh), material_(material), dofs_(dofs), Ke_(mesh.num_elements()),
      fe_(mesh.num_elements()), detF_(mesh.num_elements()) {
  elements_.reserve(mesh.num_elements());
  for (std::size_t e = 0; e < mesh.num_elements(); ++e) elements_.emplace_back(element_nodes(e));
  scatter_ = ElementScatter<n>(mesh.num_elements(), dofs_.num_free(), [&](std::size_t e, int i) {
    return dofs_.free_index(global_dof(e, i));
  });
}

template <class Family>
typename Family::Nodes BasicAssembler<Family>::element_nodes(std::size_t e) const {
  typename Family::Nodes X;
  for (std::size_t k = 0; k < nodes; ++k)
    X[k] = mesh_.X[static_cast<std::size_t>(mesh_.elements[e][k])];
  return X;
}

template <class Family>
auto BasicAssembler<Family>::gather(const Vector& u, std::size_t e) const -> ElementVector {
  ElementVector ue;
  for (std::size_t k = 0; k < nodes; ++k)
    ue.template segment<dim>(dim * static_cast<Eigen::Index>(k)) =
        u.segment<dim>(dim * mesh_.elements[e][k]);
  return ue;
}

template <class Family>
void BasicAssembler<Family>::assemble(const Vector& u, Vector& f_int, SparseMatrix* K) {
  parallel_for(elements_.size(), [&](std::size_t e) {
    detF_[e] = elements_[e].internal_force(gather(u, e), material_, fe_[e], K ? &Ke_[e] : nullptr);
  });
  for (std::size_t e = 0; e < elements_.size(); ++e)
    if (!(detF_[e] > 0.0)) {
      std::ostringstream s;
      s << "element " << Family::label(mesh_, e) << ": det F = " << detF_[e]
        << " <= 0 at a quadrature point (inverted element)";
      throw InvertedElement(s.str());
    }
  f_int.setZero(dim * static_cast<Eigen::Index>(mesh_.num_nodes()));
  for (std::size_t e = 0; e < elements_.size(); ++e)
    for (std::size_t k = 0; k < nodes; ++k)
      f_int.segment<dim>(dim * mesh_.elements[e][k]) +=
          fe_[e].template segment<dim>(dim * static_cast<Eigen::Index>(k));
  if (K) scatter_.scatter(Ke_, *K);
}

template <class Family> SparseMatrix BasicAssembler<Family>::mass() {
  parallel_for(elements_.size(), [&](std::size_t e) {
    Ke_[e] = Family::mass(element_nodes(e), material_.density());
  });
  SparseMatrix M = scatter_.pattern();
  scatter_.scatter(Ke_, M);
  return M;
}

template <class Family> SparseMatrix BasicAssembler<Family>::full_mass() const {
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(elements_.size() * n * n);
  for (std::size_t e = 0; e < elements_.size(); ++e) {
    const ElementMatrix m = Family::mass(element_nodes(e), material_.density());
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        triplets.emplace_back(global_dof(e, i), global_dof(e, j), m(i, j));
  }
  const auto size = static_cast<Eigen::Index>(dim * mesh_.num_nodes());
  SparseMatrix M(size, size);
  M.setFromTriplets(triplets.begin(), triplets.end());
  return M;
}

template <class Family> Vector BasicAssembler<Family>::gravity_forces(const VecDim& g) const {
  ElementVector g_rep;
  for (int k = 0; k < nodes; ++k) g_rep.template segment<dim>(dim * k) = g;
  Vector f = Vector::Zero(dim * static_cast<Eigen::Index>(mesh_.num_nodes()));
  for (std::size_t e = 0; e < elements_.size(); ++e) {
    const ElementVector fe =
        Family::mass(element_nodes(e), material_.density()) * g_rep; // sum_J N_J = 1 (eq. 39)
    for (std::size_t k = 0; k < nodes; ++k)
      f.segment<dim>(dim * mesh_.elements[e][k]) +=
          fe.template segment<dim>(dim * static_cast<Eigen::Index>(k));
  }
  return f;
}

template <class Family> double BasicAssembler<Family>::strain_energy(const Vector& u) const {
  return parallel_reduce(
      elements_.size(), 0.0,
      [&](std::size_t e) { return elements_[e].strain_energy(gather(u, e), material_); },
      [](double a, double b) { return a + b; });
}

template <class Family> Vector BasicAssembler<Family>::nodal_von_mises(const Vector& u) const {
  std::vector<std::array<double, nodes>> vm(elements_.size());
  parallel_for(elements_.size(), [&](std::size_t e) {
    vm[e] = Family::nodal_von_mises(element_nodes(e), gather(u, e), material_);
  });
  Vector sum = Vector::Zero(static_cast<Eigen::Index>(mesh_.num_nodes()));
  Vector count = Vector::Zero(sum.size());
  for (std::size_t e = 0; e < elements_.size(); ++e)
    for (std::size_t k = 0; k < vm[e].size(); ++k) {
      sum[mesh_.elements[e][k]] += vm[e][k];
      count[mesh_.elements[e][k]] += 1.0;
    }
  return sum.cwiseQuotient(count);
}

template class BasicAssembler<T6>;
template class BasicAssembler<T10>;

} // namespace fsi::fem
