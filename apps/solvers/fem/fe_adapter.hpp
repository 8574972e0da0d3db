#pragma once
// The coupler's S (eq. 67) for an FE structure of either element family (T6 in 2-D, T10 in 3-D):
// interface loads in as FE nodal forces (eq. 59), FE node motion out (eqs. 60-62), both through
// the node correspondence fe_node (NCR, eq. 50) of the structure's interface (fem::interface_of).
#include "coupling/interface.hpp"
#include "fem/fem_part.hpp"
#include "structure_fem/interface_mesh.hpp"
#include "structure_fem/structure.hpp"

#include <optional>

namespace fsi::app::fem_plugin {

/// The interface loads are nodal forces already: the fluid projects its point loads with the
/// interface's own edge or face shape functions (coupling::project_point_loads, eqs. 53-58), the
/// ones of the FE boundary edges and faces. The structure and the interface are referenced and
/// must outlive the adapter; each FE node is at most one interface node (fem::interface_of).
template <class Family> class BasicFeAdapter : public coupling::BasicStructureSolver<Family::dim> {
public:
  static constexpr int dim = Family::dim;

  BasicFeAdapter(fem::BasicStructure<Family>& structure,
                 const fem::BasicFeInterface<dim>& interface);
  void initialize() override {}
  /// The structure's external forces become loads.f[k] on FE node fe_node[k], zero elsewhere.
  void set_interface_loads(const coupling::BasicInterfaceLoads<dim>& loads) override;
  /// One Newmark step of the structure (t is its own clock).
  void advance(double t, double dt) override;
  /// Interface node k: x = X + u, v and a of FE node fe_node[k] (eqs. 60-62).
  coupling::BasicInterfaceMotion<dim> interface_motion() const override;
  void save_state() override;
  void restore_state() override;

private:
  fem::BasicStructure<Family>& structure_;
  const fem::BasicFeInterface<dim>& interface_;
  fem::Vector forces_; ///< the external forces set last, dim per FE node
  std::optional<fem::StructureState> saved_;
};

/// S on the structure of a scene part: the part advances and checkpoints it, so that the part's
/// Newton counters cover coupled runs too and checkpoints keep them. save_state / restore_state
/// do not roll the counters back: they count every solve, re-run evaluations too. The part and
/// the interface must outlive the adapter.
template <class Family> class PartAdapter final : public BasicFeAdapter<Family> {
public:
  PartAdapter(BasicFemPart<Family>& part, const fem::BasicFeInterface<Family::dim>& interface)
      : BasicFeAdapter<Family>(part.structure(), interface), part_(part) {}
  void advance(double t, double dt) override { part_.advance(t, dt); }
  void write_state(StateArchive& archive) const override { part_.write_state(archive); }
  void read_state(const StateArchive& archive) override { part_.read_state(archive); }

private:
  BasicFemPart<Family>& part_;
};

using FeAdapter = BasicFeAdapter<fem::T6>;
using FeAdapterT10 = BasicFeAdapter<fem::T10>;
extern template class BasicFeAdapter<fem::T6>;
extern template class BasicFeAdapter<fem::T10>;

} // namespace fsi::app::fem_plugin
