#pragma once
// Several structures as one S for the coupler (e.g. two gates): their interface nodes
// concatenated in order, loads split back by the same offsets. Each member advances, saves,
// restores and checkpoints itself (members write under their own keys).
#include "coupling/interface.hpp"

#include <vector>

namespace fsi::coupling {

class StructureGroup final : public StructureSolver {
public:
  /// Members in interface order; not owned, they must outlive the group.
  explicit StructureGroup(std::vector<StructureSolver*> members);

  void initialize() override;
  void set_interface_loads(const InterfaceLoads& loads) override;
  void advance(double t, double dt) override;
  InterfaceMotion interface_motion() const override;
  void save_state() override;
  void restore_state() override;
  void write_state(StateArchive& archive) const override;
  void read_state(const StateArchive& archive) override;
  void finalize() override;

private:
  std::vector<StructureSolver*> members_;
  std::vector<std::size_t> offset_; ///< first node of each member, and the total (initialize)
  InterfaceLoads part_;
};

} // namespace fsi::coupling
