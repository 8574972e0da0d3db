#pragma once
// Dirichlet conditions and the numbering of the free degrees of freedom, for T6 and T10 meshes.
#include <array>
#include <functional>
#include <string>
#include <vector>

#include "structure_fem/mesh.hpp"
#include "structure_fem/mesh_t10.hpp"
#include "structure_fem/types.hpp"

namespace fsi::fem {

/// Displacement, velocity and acceleration prescribed on a node at one time.
template <int D> struct BasicPrescribedKinematics {
  VecD<D> u = VecD<D>::Zero(), v = VecD<D>::Zero(), a = VecD<D>::Zero();
};
using PrescribedKinematics = BasicPrescribedKinematics<2>;
using PrescribedKinematics3 = BasicPrescribedKinematics<3>;

/// The prescribed kinematics of the node with reference position X at time t (e.g. the rigid
/// motion of the tank a beam is clamped to). Must be a pure function of (X, t): a step may be
/// re-run after restore().
template <int D>
using BasicPrescribedMotion =
    std::function<BasicPrescribedKinematics<D>(const VecD<D>& X, double t)>;
using PrescribedMotion = BasicPrescribedMotion<2>;
using PrescribedMotion3 = BasicPrescribedMotion<3>;

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

/// A clamped (u = 0), sliding (some components fixed) or moving T10 boundary: the chosen
/// components of every node of the faces tagged `tag`, or, if `tag` is empty, of the listed node
/// indices; without a motion they are zero, with one they follow motion(X, t).
struct DirichletCondition3 {
  std::string tag;
  std::array<bool, 3> fix{true, true, true};
  std::vector<int> nodes;
  PrescribedMotion3 motion = {};
};

/// Numbering of the free degrees of freedom. Dof dim K + c is component c of node K.
class DofMap {
public:
  /// Throws InputError if a tag names no boundary edge or a node index is out of range.
  DofMap(const Mesh& mesh, const std::vector<DirichletCondition>& conditions);
  /// The same for a T10 mesh and its tagged faces.
  DofMap(const TetMesh& mesh, const std::vector<DirichletCondition3>& conditions);
  int dim() const { return dim_; }
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
  DofMap(std::size_t num_nodes, int dim);
  /// Marks component c of node K constrained by condition i (K checked against the range).
  void constrain(int node, int c, int i);
  /// Numbers the unconstrained dofs.
  void number_free();

  int dim_;
  std::vector<int> free_of_dof_;
  std::vector<int> condition_of_dof_;
  int num_free_ = 0;
};

} // namespace fsi::fem
