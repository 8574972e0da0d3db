#pragma once
// Global assembly over T10 elements (issue 44), the 3-D counterpart of Assembler: the same
// pattern and scatter (ElementScatter), element matrices computed in parallel into a buffer and
// summed serially in element order. Node arrays have size 3 * nodes, entry 3K + c.
#include <vector>

#include "structure_fem/assembly.hpp"
#include "structure_fem/element_scatter.hpp"
#include "structure_fem/element_t10.hpp"
#include "structure_fem/mesh_t10.hpp"

namespace fsi::fem {

class AssemblerT10 {
public:
  /// Keeps references to mesh, material and dofs: they must outlive the assembler.
  AssemblerT10(const TetMesh& mesh, const Material3& material, const DofMap& dofs);

  /// Sparsity pattern on the free dofs (all values zero), full symmetric storage.
  const SparseMatrix& pattern() const { return scatter_.pattern(); }
  /// Internal forces on all dofs and, if K is given, the tangent on the free dofs (K with
  /// pattern()'s structure). Throws InvertedElement naming the first element with det F <= 0.
  void assemble(const Vector& u, Vector& f_int, SparseMatrix* K);
  /// Consistent mass on the free dofs, with pattern()'s structure.
  SparseMatrix mass();
  /// Consistent body force of gravity g [m/s^2] on all dofs: f_K = integral rho N_K g.
  Vector gravity_forces(const Vec3& g) const;
  /// Total strain energy, the integral of W(E) [J].
  double strain_energy(const Vector& u) const;

private:
  Vec30 gather(const Vector& u, std::size_t e) const;
  TetNodes element_nodes(std::size_t e) const;

  const TetMesh& mesh_;
  const Material3& material_;
  const DofMap& dofs_;
  std::vector<ElementT10> elements_;
  ElementScatter<30> scatter_;
  std::vector<Mat30> Ke_;    ///< element matrix buffer
  std::vector<Vec30> fe_;    ///< element vector buffer
  std::vector<double> detF_; ///< smallest det F per element in the last assembly
};

} // namespace fsi::fem
