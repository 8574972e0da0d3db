#pragma once
// The run's finite-value guard over what the models move (issue 41): walls and structure nodes
// as well as particles, each model naming its first non-finite point (Model::non_finite).
#include "fsi/core/types.hpp"

#include <optional>
#include <string>

namespace fsi::app {

/// "WHAT at (x, y) m, velocity (vx, vy) m/s" when x or v is not finite, else nothing.
std::optional<std::string> non_finite_point(const std::string& what, const Vec2& x, const Vec2& v);
/// The same in 3-D, "(x, y, z)".
std::optional<std::string> non_finite_point3(const std::string& what, const Vec3& x, const Vec3& v);

} // namespace fsi::app
