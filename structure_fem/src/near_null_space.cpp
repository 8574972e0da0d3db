#include "structure_fem/near_null_space.hpp"

#include <Eigen/Geometry>

namespace fsi::fem {

template <int D> NearNullSpace rigid_body_modes(const DofMap& dofs, const std::vector<VecD<D>>& X) {
  constexpr int rotations = D == 2 ? 1 : 3;
  VecD<D> centroid = VecD<D>::Zero();
  for (const auto& x : X) centroid += x / static_cast<double>(X.size());
  NearNullSpace b{Eigen::MatrixXd::Zero(dofs.num_free(), D + rotations), {}};
  b.node.reserve(static_cast<std::size_t>(dofs.num_free()));
  for (int d = 0; d < dofs.num_dofs(); ++d) {
    const int i = dofs.free_index(d);
    if (i < 0) continue;
    const int c = d % D;
    const VecD<D> y = X[static_cast<std::size_t>(d / D)] - centroid;
    b.node.push_back(d / D);
    b.modes(i, c) = 1.0; // translation along c
    // Rotation about axis k: component c of e_k x y.
    if constexpr (D == 2)
      b.modes(i, 2) = c == 0 ? -y.y() : y.x();
    else
      for (int k = 0; k < 3; ++k) b.modes(i, 3 + k) = Vec3::Unit(k).cross(Vec3(y))[c];
  }
  return b;
}

template NearNullSpace rigid_body_modes<2>(const DofMap&, const std::vector<Vec2>&);
template NearNullSpace rigid_body_modes<3>(const DofMap&, const std::vector<Vec3>&);

} // namespace fsi::fem
