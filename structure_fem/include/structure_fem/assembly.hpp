#pragma once
// Global assembly over T6 or T10 elements, one template over the element family: the sparse
// pattern on the free degrees of freedom is built once; element matrices are computed in
// parallel (fsi::parallel_for) into a preallocated buffer and scattered serially in element
// order, so results do not depend on the thread count. Node arrays have size dim * nodes.
#include <string>
#include <vector>

#include "fsi/core/error.hpp"
#include "structure_fem/dof_map.hpp"
#include "structure_fem/element_scatter.hpp"
#include "structure_fem/element_t10.hpp"
#include "structure_fem/element_t6.hpp"
#include "structure_fem/mesh.hpp"
#include "structure_fem/mesh_t10.hpp"

namespace fsi::fem {

/// det F <= 0 at a quadrature point: thrown by Assembler::assemble; Newton halves an increment
/// that leads there (newton_raphson), any other caller stops the run.
struct InvertedElement : RunError {
  using RunError::RunError;
};

/// The 6-node triangle (2-D, per unit thickness).
struct T6 {
  static constexpr int dim = 2, nodes = 6;
  using Mesh = fem::Mesh;
  using Element = ElementT6;
  using Material = fem::Material;
  using Nodes = ElementNodes;
  using Condition = DirichletCondition;
  static Mat12 mass(const Nodes& X, double rho) { return t6_mass(X, rho); }
  static std::array<double, 6> nodal_von_mises(const Nodes& X, const Vec12& u,
                                               const Material& law) {
    return t6_nodal_von_mises(X, u, law);
  }
  static long label(const Mesh& mesh, std::size_t e) { return mesh.element_label[e]; }
};

/// The 10-node tetrahedron (3-D).
struct T10 {
  static constexpr int dim = 3, nodes = 10;
  using Mesh = TetMesh;
  using Element = ElementT10;
  using Material = Material3;
  using Nodes = TetNodes;
  using Condition = DirichletCondition3;
  static Mat30 mass(const Nodes& X, double rho) { return t10_mass(X, rho); }
  static std::array<double, 10> nodal_von_mises(const Nodes& X, const Vec30& u,
                                                const Material& law) {
    return t10_nodal_von_mises(X, u, law);
  }
  static long label(const Mesh&, std::size_t e) { return static_cast<long>(e) + 1; }
};

template <class Family> class BasicAssembler {
public:
  static constexpr int dim = Family::dim, nodes = Family::nodes, n = dim * nodes;
  using ElementVector = Eigen::Matrix<double, n, 1>;
  using ElementMatrix = Eigen::Matrix<double, n, n>;
  using VecDim = Eigen::Matrix<double, dim, 1>;

  /// Keeps references to mesh, material and dofs: they must outlive the assembler.
  /// Precomputes the per-element quadrature data, the pattern and the scatter map.
  BasicAssembler(const typename Family::Mesh& mesh, const typename Family::Material& material,
                 const DofMap& dofs);

  /// Sparsity pattern on the free dofs (all values zero), full symmetric storage.
  const SparseMatrix& pattern() const { return scatter_.pattern(); }
  /// Internal forces on all dofs (size dim * nodes) and, if K is given, the tangent on the free
  /// dofs (K must have pattern()'s structure; its values are overwritten). Throws
  /// InvertedElement naming the first element with det F <= 0 at a quadrature point.
  void assemble(const Vector& u, Vector& f_int, SparseMatrix* K);
  /// Consistent mass on the free dofs, with pattern()'s structure.
  SparseMatrix mass();
  /// Consistent mass on all dofs (dim * nodes square): its free-constrained block carries the
  /// inertia of prescribed accelerations into the free equations.
  SparseMatrix full_mass() const;
  /// Consistent body force of gravity g [m/s^2] on all dofs: f_K = integral rho N_K g.
  Vector gravity_forces(const VecDim& g) const;
  /// Total strain energy integral W(E) [J] (T6: per unit thickness, J/m).
  double strain_energy(const Vector& u) const;
  /// Von Mises Cauchy stress per node, averaged over the elements sharing the node [Pa].
  Vector nodal_von_mises(const Vector& u) const;

private:
  ElementVector gather(const Vector& u, std::size_t e) const;
  typename Family::Nodes element_nodes(std::size_t e) const;
  /// Global dof of element dof i of element e.
  int global_dof(std::size_t e, int i) const {
    return dim * mesh_.elements[e][static_cast<std::size_t>(i / dim)] + i % dim;
  }

  const typename Family::Mesh& mesh_;
  const typename Family::Material& material_;
  const DofMap& dofs_;
  std::vector<typename Family::Element> elements_;
  ElementScatter<n> scatter_;
  std::vector<ElementMatrix> Ke_; ///< element matrix buffer
  std::vector<ElementVector> fe_; ///< element vector buffer
  std::vector<double> detF_;      ///< smallest det F per element in the last assembly
};

using Assembler = BasicAssembler<T6>;
using AssemblerT10 = BasicAssembler<T10>;
extern template class BasicAssembler<T6>;
extern template class BasicAssembler<T10>;

} // namespace fsi::fem
