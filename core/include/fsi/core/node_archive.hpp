#pragma once
// A node set's x, v, a in a checkpoint (the nodes of moving walls).
#include "fsi/core/node_motion.hpp"
#include "fsi/core/state_archive.hpp"

#include <string>

namespace fsi {

/// Puts n's x, v, a under `prefix` + "x", "v", "a", flattened (flatten).
template <int D>
void put_nodes(StateArchive& archive, const std::string& prefix, const BasicNodeMotion<D>& n) {
  archive.put(prefix + "x", flatten(n.x));
  archive.put(prefix + "v", flatten(n.v));
  archive.put(prefix + "a", flatten(n.a));
}

/// Reads what put_nodes wrote into `n`, whose size the entries must match (InputError naming the
/// key otherwise).
template <int D>
void read_nodes(const StateArchive& archive, const std::string& prefix, BasicNodeMotion<D>& n) {
  const std::size_t size = D * n.size();
  n.x = unflatten<D>(archive.reals(prefix + "x", size));
  n.v = unflatten<D>(archive.reals(prefix + "v", size));
  n.a = unflatten<D>(archive.reals(prefix + "a", size));
}

} // namespace fsi
