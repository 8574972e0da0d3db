#pragma once
// Several structures as one S for the coupler (e.g. two gates): their interface nodes
// concatenated in order, loads split back by the same offsets. Each member advances, saves,
// restores and checkpoints itself (members write under their own keys). BasicStructureGroup<D>
// for D = 2 (StructureGroup) and 3 (StructureGroup3).
#include "coupling/interface.hpp"

#include <vector>

namespace fsi::coupling {

template <int D> class BasicStructureGroup final : public BasicStructureSolver<D> {
public:
  /// Members in interface order; not owned, they must outlive the group.
  explicit BasicStructureGroup(std::vector<BasicStructureSolver<D>*> members);

  void initialize() override;
  void set_interface_loads(const BasicInterfaceLoads<D>& loads) override;
  void advance(double t, double dt) override;
  BasicInterfaceMotion<D> interface_motion() const override;
  void save_state() override;
  void restore_state() override;
  void write_state(StateArchive& archive) const override;
  void read_state(const StateArchive& archive) override;
  void finalize() override;

private:
  std::vector<BasicStructureSolver<D>*> members_;
  std::vector<std::size_t> offset_; ///< first node of each member, and the total (initialize)
  BasicInterfaceLoads<D> part_;
};

extern template class BasicStructureGroup<2>;
extern template class BasicStructureGroup<3>;
using StructureGroup = BasicStructureGroup<2>;
using StructureGroup3 = BasicStructureGroup<3>;

} // namespace fsi::coupling
