#include "structure_fem/assembly.hpp"

#include <algorithm>
#include <sstream>

#include "fsi/core/error.hpp"
#include "fsi/core/parallel.hpp"

namespace fsi::fem {

Assembler::Assembler(const Mesh& mesh, const Material& material, const DofMap& dofs)
    : mesh_(mesh), material_(material), dofs_(dofs), Ke_(mesh.num_elements()),
      fe_(mesh.num_elements()), detF_(mesh.num_elements()) {
  const std::size_t n_el = mesh.num_elements();
  elements_.reserve(n_el);
  for (std::size_t e = 0; e < n_el; ++e) elements_.emplace_back(element_nodes(e));

  scatter_ = ElementScatter<12>(n_el, dofs_.num_free(), [&](std::size_t e, int i) {
    return dofs_.free_index(2 * mesh_.elements[e][static_cast<std::size_t>(i / 2)] + i % 2);
  });
}

ElementNodes Assembler::element_nodes(std::size_t e) const {
  ElementNodes X;
  for (std::size_t k = 0; k < 6; ++k)
    X[k] = mesh_.X[static_cast<std::size_t>(mesh_.elements[e][k])];
  return X;
}

Vec12 Assembler::gather(const Vector& u, std::size_t e) const {
  Vec12 ue;
  for (std::size_t k = 0; k < 6; ++k)
    ue.segment<2>(2 * static_cast<Eigen::Index>(k)) = u.segment<2>(2 * mesh_.elements[e][k]);
  return ue;
}

void Assembler::assemble(const Vector& u, Vector& f_int, SparseMatrix* K) {
  parallel_for(elements_.size(), [&](std::size_t e) {
    detF_[e] = elements_[e].internal_force(gather(u, e), material_, fe_[e], K ? &Ke_[e] : nullptr);
  });
  for (std::size_t e = 0; e < elements_.size(); ++e)
    if (!(detF_[e] > 0.0)) {
      std::ostringstream s;
      s << "element " << mesh_.element_label[e] << ": det F = " << detF_[e]
        << " <= 0 at a quadrature point (inverted element)";
      throw InvertedElement(s.str());
    }
  f_int.setZero(2 * static_cast<Eigen::Index>(mesh_.num_nodes()));
  for (std::size_t e = 0; e < elements_.size(); ++e)
    for (std::size_t k = 0; k < 6; ++k)
      f_int.segment<2>(2 * mesh_.elements[e][k]) +=
          fe_[e].segment<2>(2 * static_cast<Eigen::Index>(k));
  if (K) scatter_.scatter(Ke_, *K);
}

SparseMatrix Assembler::mass() {
  parallel_for(elements_.size(),
               [&](std::size_t e) { Ke_[e] = t6_mass(element_nodes(e), material_.density()); });
  SparseMatrix M = scatter_.pattern();
  scatter_.scatter(Ke_, M);
  return M;
}

SparseMatrix Assembler::full_mass() const {
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(elements_.size() * 144);
  for (std::size_t e = 0; e < elements_.size(); ++e) {
    const Mat12 m = t6_mass(element_nodes(e), material_.density());
    for (int j = 0; j < 12; ++j)
      for (int i = 0; i < 12; ++i)
        triplets.emplace_back(2 * mesh_.elements[e][static_cast<std::size_t>(i / 2)] + i % 2,
                              2 * mesh_.elements[e][static_cast<std::size_t>(j / 2)] + j % 2,
                              m(i, j));
  }
  const auto n = static_cast<Eigen::Index>(2 * mesh_.num_nodes());
  SparseMatrix M(n, n);
  M.setFromTriplets(triplets.begin(), triplets.end());
  return M;
}

Vector Assembler::gravity_forces(const Vec2& g) {
  Vec12 g_rep;
  for (int k = 0; k < 6; ++k) g_rep.segment<2>(2 * k) = g;
  Vector f = Vector::Zero(2 * static_cast<Eigen::Index>(mesh_.num_nodes()));
  for (std::size_t e = 0; e < elements_.size(); ++e) {
    const Vec12 fe =
        t6_mass(element_nodes(e), material_.density()) * g_rep; // sum_J N_J = 1 (eq. 39)
    for (std::size_t k = 0; k < 6; ++k)
      f.segment<2>(2 * mesh_.elements[e][k]) += fe.segment<2>(2 * static_cast<Eigen::Index>(k));
  }
  return f;
}

double Assembler::strain_energy(const Vector& u) const {
  return parallel_reduce(
      elements_.size(), 0.0,
      [&](std::size_t e) { return elements_[e].strain_energy(gather(u, e), material_); },
      [](double a, double b) { return a + b; });
}

Vector Assembler::nodal_von_mises(const Vector& u) const {
  std::vector<std::array<double, 6>> vm(elements_.size());
  parallel_for(elements_.size(), [&](std::size_t e) {
    vm[e] = t6_nodal_von_mises(element_nodes(e), gather(u, e), material_);
  });
  Vector sum = Vector::Zero(static_cast<Eigen::Index>(mesh_.num_nodes()));
  Vector count = Vector::Zero(sum.size());
  for (std::size_t e = 0; e < elements_.size(); ++e)
    for (std::size_t k = 0; k < 6; ++k) {
      sum[mesh_.elements[e][k]] += vm[e][k];
      count[mesh_.elements[e][k]] += 1.0;
    }
  return sum.cwiseQuotient(count);
}

} // namespace fsi::fem
