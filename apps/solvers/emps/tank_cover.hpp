#pragma once
// Where a structure's wetted surface lies on the tank's wall (a plate forming the tank's floor),
// the fluid sees the structure there and not a second, rigid wall: a tank triangle wholly covered
// by the interfaces' faces (in its plane within `tolerance`) is left out. A partial cover would
// leave a rigid wall and a moving one over the same area: it is refused.
#include "fsi/core/interface_mesh.hpp"
#include "fsi/core/types.hpp"

#include <array>
#include <span>
#include <vector>

namespace fsi::app::emps_plugin {

/// The triangles of `triangles` (over `points`) not wholly covered by the interfaces' faces: a
/// face counts when its three corners lie within `tolerance` of the triangle's plane; the area
/// of each such face inside the triangle is summed (the faces of a surface do not overlap), and
/// the triangle is covered when the sum reaches its area within 1e-9 of it. Throws InputError
/// naming the triangle (1-based), its share covered and the interface when the cover is partial.
std::vector<std::array<int, 3>> uncovered_triangles(std::span<const Vec3> points,
                                                    std::span<const std::array<int, 3>> triangles,
                                                    const std::vector<InterfaceMesh3>& interfaces,
                                                    double tolerance);

} // namespace fsi::app::emps_plugin
