#include "coupling/structure_group.hpp"

#include <cassert>

namespace fsi::coupling {

template <int D>
BasicStructureGroup<D>::BasicStructureGroup(std::vector<BasicStructureSolver<D>*> members)
    : members_(std::move(members)) {}

template <int D> void BasicStructureGroup<D>::initialize() {
  offset_ = {0};
  for (auto* m : members_) {
    m->initialize();
    offset_.push_back(offset_.back() + m->interface_motion().size());
  }
}

template <int D>
void BasicStructureGroup<D>::set_interface_loads(const BasicInterfaceLoads<D>& loads) {
  assert(!offset_.empty() && "StructureGroup::set_interface_loads before initialize");
  assert(loads.size() == offset_.back());
  for (std::size_t j = 0; j < members_.size(); ++j) {
    part_.f.assign(loads.f.begin() + static_cast<std::ptrdiff_t>(offset_[j]),
                   loads.f.begin() + static_cast<std::ptrdiff_t>(offset_[j + 1]));
    members_[j]->set_interface_loads(part_);
  }
}

template <int D> void BasicStructureGroup<D>::advance(double t, double dt) {
  for (auto* m : members_) m->advance(t, dt);
}

template <int D> BasicInterfaceMotion<D> BasicStructureGroup<D>::interface_motion() const {
  BasicInterfaceMotion<D> all;
  for (const auto* m : members_) {
    const BasicInterfaceMotion<D> one = m->interface_motion();
    all.x.insert(all.x.end(), one.x.begin(), one.x.end());
    all.v.insert(all.v.end(), one.v.begin(), one.v.end());
    all.a.insert(all.a.end(), one.a.begin(), one.a.end());
  }
  return all;
}

template <int D> void BasicStructureGroup<D>::save_state() {
  for (auto* m : members_) m->save_state();
}

template <int D> void BasicStructureGroup<D>::restore_state() {
  for (auto* m : members_) m->restore_state();
}

template <int D> void BasicStructureGroup<D>::write_state(StateArchive& archive) const {
  for (const auto* m : members_) m->write_state(archive);
}

template <int D> void BasicStructureGroup<D>::read_state(const StateArchive& archive) {
  for (auto* m : members_) m->read_state(archive);
}

template <int D> void BasicStructureGroup<D>::finalize() {
  for (auto* m : members_) m->finalize();
}

template class BasicStructureGroup<2>;
template class BasicStructureGroup<3>;

} // namespace fsi::coupling
