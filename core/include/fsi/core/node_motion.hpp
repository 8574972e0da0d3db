#pragma once
// Positions x [m], velocities v [m/s] and accelerations a [m/s^2] of a set of nodes at one
// instant, struct-of-arrays (x, v, a have the same size): the coupling's interface state
// (eqs. 60-62 of the EMPS-ERP-FEM paper) and the ERP polygon nodes L are both this.
// BasicNodeMotion<D> for D = 2 (NodeMotion) and 3 (NodeMotion3).
#include "fsi/core/types.hpp"

#include <cstddef>
#include <vector>

namespace fsi {

template <int D> struct BasicNodeMotion {
  std::vector<VecD<D>> x, v, a;

  std::size_t size() const { return x.size(); }
  /// n nodes, all zero.
  static BasicNodeMotion zeros(std::size_t n) {
    BasicNodeMotion m;
    m.x.assign(n, VecD<D>::Zero());
    m.v.assign(n, VecD<D>::Zero());
    m.a.assign(n, VecD<D>::Zero());
    return m;
  }
};

using NodeMotion = BasicNodeMotion<2>;
using NodeMotion3 = BasicNodeMotion<3>;

} // namespace fsi
