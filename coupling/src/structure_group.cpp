#include "coupling/structure_group.hpp"

#include <cassert>

namespace fsi::coupling {

StructureGroup::StructureGroup(std::vector<StructureSolver*> members)
    : members_(std::move(members)) {}

void StructureGroup::initialize() {
  offset_ = {0};
  for (auto* m : members_) {
    m->initialize();
    offset_.push_back(offset_.back() + m->interface_motion().size());
  }
}

void StructureGroup::set_interface_loads(const InterfaceLoads& loads) {
  assert(!offset_.empty() && "StructureGroup::set_interface_loads before initialize");
  assert(loads.size() == offset_.back());
  for (std::size_t j = 0; j < members_.size(); ++j) {
    part_.f.assign(loads.f.begin() + static_cast<std::ptrdiff_t>(offset_[j]),
                   loads.f.begin() + static_cast<std::ptrdiff_t>(offset_[j + 1]));
    members_[j]->set_interface_loads(part_);
  }
}

void StructureGroup::advance(double t, double dt) {
  for (auto* m : members_) m->advance(t, dt);
}

InterfaceMotion StructureGroup::interface_motion() const {
  InterfaceMotion all;
  for (const auto* m : members_) {
    const InterfaceMotion one = m->interface_motion();
    all.x.insert(all.x.end(), one.x.begin(), one.x.end());
    all.v.insert(all.v.end(), one.v.begin(), one.v.end());
    all.a.insert(all.a.end(), one.a.begin(), one.a.end());
  }
  return all;
}

void StructureGroup::save_state() {
  for (auto* m : members_) m->save_state();
}

void StructureGroup::restore_state() {
  for (auto* m : members_) m->restore_state();
}

void StructureGroup::write_state(StateArchive& archive) const {
  for (const auto* m : members_) m->write_state(archive);
}

void StructureGroup::read_state(const StateArchive& archive) {
  for (auto* m : members_) m->read_state(archive);
}

void StructureGroup::finalize() {
  for (auto* m : members_) m->finalize();
}

} // namespace fsi::coupling
