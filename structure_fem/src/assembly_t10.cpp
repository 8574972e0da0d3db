#include "structure_fem/assembly_t10.hpp"

#include <sstream>

#include "fsi/core/parallel.hpp"

namespace fsi::fem {

AssemblerT10::AssemblerT10(const TetMesh& mesh, const Material3& material, const DofMap& dofs)
    : mesh_(mesh), material_(material), dofs_(dofs), Ke_(mesh.num_elements()),
      fe_(mesh.num_elements()), detF_(mesh.num_elements()) {
  elements_.reserve(mesh.num_elements());
  for (std::size_t e = 0; e < mesh.num_elements(); ++e) elements_.emplace_back(element_nodes(e));
  scatter_ = ElementScatter<30>(mesh.num_elements(), dofs_.num_free(), [&](std::size_t e, int i) {
    return dofs_.free_index(3 * mesh_.elements[e][static_cast<std::size_t>(i / 3)] + i % 3);
  });
}

TetNodes AssemblerT10::element_nodes(std::size_t e) const {
  TetNodes X;
  for (std::size_t k = 0; k < 10; ++k)
    X[k] = mesh_.X[static_cast<std::size_t>(mesh_.elements[e][k])];
  return X;
}

Vec30 AssemblerT10::gather(const Vector& u, std::size_t e) const {
  Vec30 ue;
  for (std::size_t k = 0; k < 10; ++k)
    ue.segment<3>(3 * static_cast<Eigen::Index>(k)) = u.segment<3>(3 * mesh_.elements[e][k]);
  return ue;
}

void AssemblerT10::assemble(const Vector& u, Vector& f_int, SparseMatrix* K) {
  parallel_for(elements_.size(), [&](std::size_t e) {
    detF_[e] = elements_[e].internal_force(gather(u, e), material_, fe_[e], K ? &Ke_[e] : nullptr);
  });
  for (std::size_t e = 0; e < elements_.size(); ++e)
    if (!(detF_[e] > 0.0)) {
      std::ostringstream s;
      s << "element " << e + 1 << ": det F = " << detF_[e]
        << " <= 0 at a quadrature point (inverted element)";
      throw InvertedElement(s.str());
    }
  f_int.setZero(3 * static_cast<Eigen::Index>(mesh_.num_nodes()));
  for (std::size_t e = 0; e < elements_.size(); ++e)
    for (std::size_t k = 0; k < 10; ++k)
      f_int.segment<3>(3 * mesh_.elements[e][k]) +=
          fe_[e].segment<3>(3 * static_cast<Eigen::Index>(k));
  if (K) scatter_.scatter(Ke_, *K);
}

SparseMatrix AssemblerT10::mass() {
  parallel_for(elements_.size(),
               [&](std::size_t e) { Ke_[e] = t10_mass(element_nodes(e), material_.density()); });
  SparseMatrix M = scatter_.pattern();
  scatter_.scatter(Ke_, M);
  return M;
}

Vector AssemblerT10::gravity_forces(const Vec3& g) const {
  Vec30 g_rep;
  for (int k = 0; k < 10; ++k) g_rep.segment<3>(3 * k) = g;
  Vector f = Vector::Zero(3 * static_cast<Eigen::Index>(mesh_.num_nodes()));
  for (std::size_t e = 0; e < elements_.size(); ++e) {
    const Vec30 fe = t10_mass(element_nodes(e), material_.density()) * g_rep; // sum_J N_J = 1
    for (std::size_t k = 0; k < 10; ++k)
      f.segment<3>(3 * mesh_.elements[e][k]) += fe.segment<3>(3 * static_cast<Eigen::Index>(k));
  }
  return f;
}

double AssemblerT10::strain_energy(const Vector& u) const {
  return parallel_reduce(
      elements_.size(), 0.0,
      [&](std::size_t e) { return elements_[e].strain_energy(gather(u, e), material_); },
      [](double a, double b) { return a + b; });
}

} // namespace fsi::fem
