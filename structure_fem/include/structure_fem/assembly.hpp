#pragma once
// Global assembly over T6 elements: the sparse pattern on the free degrees of freedom is built
// once; element matrices are computed in parallel (fsi::parallel_for) into a preallocated buffer
// and scattered serially in element order, so results do not depend on the thread count.
#include <functional>
#include <string>
#include <vector>

#include "fsi/core/error.hpp"
#include "structure_fem/element_t6.hpp"
#include "structure_fem/mesh.hpp"

namespace fsi::fem {

/// Displacement, velocity and acceleration prescribed on a node at one time.
struct PrescribedKinematics {
  Vec2 u = Vec2::Zero(), v = Vec2::Zero(), a = Vec2::Zero();
};

/// The prescribed kinematics of the node with reference position X at time t (e.g. the rigid
/// motion of the tank a beam is clamped to). Must be a pure function of (X, t): a step may be
/// re-run after restore().
using PrescribedMotion = std::function<PrescribedKinematics(const Vec2& X, double t)>;

/// Prescribed displacement of the chosen components on every node of the edges tagged `tag`, or,
/// if `tag` is empty, on the listed node indices (fix_x only: a roller sliding along y). Without a
/// motion the displacement is zero; with one, the chosen components follow motion(X, t).
struct DirichletCondition {
  std::string tag;
  bool fix_x = true;
  bool fix_y = true;
  std::vector<int> nodes;
  PrescribedMotion motion = {};
};

/// Numbering of the free degrees of freedom. Dof 2K + c is component c of node K.
class DofMap {
public:
  /// Throws InputError if a tag names no boundary edge or a node index is out of range.
  DofMap(const Mesh& mesh, const std::vector<DirichletCondition>& conditions);
  int num_dofs() const { return static_cast<int>(free_of_dof_.size()); }
  int num_free() const { return num_free_; }
  /// Index among the free dofs, or -1 if the dof is constrained.
  int free_index(int dof) const { return free_of_dof_[static_cast<std::size_t>(dof)]; }
  /// The condition (index into the constructor's list) that constrains the dof; the last one
  /// listed wins. -1 for a free dof.
  int condition(int dof) const { return condition_of_dof_[static_cast<std::size_t>(dof)]; }
  Vector restrict_to_free(const Vector& full) const;
  /// full[dof] += free[free_index(dof)] for every free dof.
  void add_free(const Vector& free, Vector& full) const;

private:
  std::vector<int> free_of_dof_;
  std::vector<int> condition_of_dof_;
  int num_free_ = 0;
};

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
  const SparseMatrix& pattern() const { return pattern_; }
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
  void scatter_matrices(SparseMatrix& A) const;

  const Mesh& mesh_;
  const Material& material_;
  const DofMap& dofs_;
  std::vector<ElementT6> elements_;
  SparseMatrix pattern_;
  std::vector<int> slot_;    ///< per element, 144 value positions in pattern_ (-1: constrained)
  std::vector<Mat12> Ke_;    ///< element matrix buffer
  std::vector<Vec12> fe_;    ///< element vector buffer
  std::vector<double> detF_; ///< smallest det F per element in the last assembly
};

} // namespace fsi::fem
