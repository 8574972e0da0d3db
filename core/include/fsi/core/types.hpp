#pragma once
// Small fixed-size types shared by all libraries. The dimension D (2 or 3) is a template parameter
// (docs/architecture.md, "Two and three dimensions"): VecD<D> and MatD<D> are written once and
// instantiated for both; Vec2 / Mat2 are the D = 2 instances every 2-D code uses.
#include <Eigen/Core>

namespace fsi {

template <int D> using VecD = Eigen::Matrix<double, D, 1>;
template <int D> using MatD = Eigen::Matrix<double, D, D>;

using Vec2 = VecD<2>;
using Vec3 = VecD<3>;
using Mat2 = MatD<2>;
using Mat3 = MatD<3>;

} // namespace fsi
