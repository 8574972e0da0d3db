#pragma once
// Global assembly over T6 elements: the sparse pattern on the free degrees of freedom is built
// once; element matrices are computed in parallel (fsi::parallel_for) into a preallocated buffer
// and scattered serially in element order, so results do not depend on the thread count.
#include <string>
#include <vector>

#include "fsi/core/error.hpp"
#include "structure_fem/dof_map.hpp"
#include "structure_fem/element_scatter.hpp"
#include "structure_fem/element_t6.hpp"
#include "structure_fem/mesh.hpp"

namespace fsi::fem {

/// det F <= 0 at a quadrature point: thrown by Assembler::assemble; Newton halves an increment
/// that leads there (Structure::newton), any other caller stops the run.
struct InvertedElement : RunError {
  using RunError::RunError;
};

class Assembler {
public:
  /// Keeps references to mesh, material and dofs: they must outlive the assembler.
  /// Precomputes the per-element quadrature data, the pattern and the scatter map.
  Assembler(const Mesh& mesh, const Material& material, const DofMap& dofs);

  /// Sparsity pattern on the free dofs (all values zero), full symmetric storage.
  const SparseMatrix& pattern() const { return scatter_.pattern(); }
  /// Internal forces on all dofs (size 2 * nodes) and, if K is given, the tangent on the free
  /// dofs (K must have pattern()'s structure; its values are overwritten). Throws RunError naming
  /// the first element with det F <= 0 at a quadrature point.
  void assemble(const Vector& u, Vector& f_int, SparseMatrix* K);
  /// Consistent mass on the free dofs, with pattern()'s structure.
  SparseMatrix mass();
  /// Consistent mass on all dofs (2 * nodes square): its free-constrained block carries the
  /// inertia of prescribed accelerations into the free equations.
  SparseMatrix full_mass() const;
  /// Consistent body force of gravity g [m/s^2] on all dofs: f_K = integral rho N_K g.
  Vector gravity_forces(const Vec2& g);
  /// Total strain energy integral W(E) (per unit thickness) [J/m].
  double strain_energy(const Vector& u) const;
  /// Von Mises Cauchy stress per node, averaged over the elements sharing the node [Pa].
  Vector nodal_von_mises(const Vector& u) const;

private:
  Vec12 gather(const Vector& u, std::size_t e) const;
  ElementNodes element_nodes(std::size_t e) const;

  const Mesh& mesh_;
  const Material& material_;
  const DofMap& dofs_;
  std::vector<ElementT6> elements_;
  ElementScatter<12> scatter_;
  std::vector<Mat12> Ke_;    ///< element matrix buffer
  std::vector<Vec12> fe_;    ///< element vector buffer
  std::vector<double> detF_; ///< smallest det F per element in the last assembly
};

} // namespace fsi::fem
