#pragma once
// Small fixed-size types shared by all libraries. The framework is two-dimensional (x, y).
#include <Eigen/Core>

namespace fsi {

using Vec2 = Eigen::Vector2d;
using Mat2 = Eigen::Matrix2d;

} // namespace fsi
