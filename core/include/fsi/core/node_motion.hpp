#pragma once
// Positions x [m], velocities v [m/s] and accelerations a [m/s^2] of a set of nodes at one
// instant, struct-of-arrays (x, v, a have the same size): the coupling's interface state
// (eqs. 60-62 of the EMPS-ERP-FEM paper) and the ERP polygon nodes L are both this.
#include "fsi/core/types.hpp"

#include <cstddef>
#include <vector>

namespace fsi {

struct NodeMotion {
  std::vector<Vec2> x, v, a;

  std::size_t size() const { return x.size(); }
  /// n nodes, all zero.
  static NodeMotion zeros(std::size_t n) {
    NodeMotion m;
    m.x.assign(n, Vec2::Zero());
    m.v.assign(n, Vec2::Zero());
    m.a.assign(n, Vec2::Zero());
    return m;
  }
};

} // namespace fsi
