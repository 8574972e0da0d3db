#pragma once
// Fixed-size and sparse types of the T6 solid. Node arrays are interleaved: entry 2K + c is
// component c (0 = x, 1 = y) of node K.
#include <Eigen/Core>
#include <Eigen/LU>
#include <Eigen/SparseCore>

#include "fsi/core/types.hpp"

namespace fsi::fem {

using Vec12 = Eigen::Matrix<double, 12, 1>;
using Mat12 = Eigen::Matrix<double, 12, 12>;
using Mat3 = Eigen::Matrix3d;
using Vector = Eigen::VectorXd;
using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

} // namespace fsi::fem
