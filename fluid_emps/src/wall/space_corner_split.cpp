// The images' term behind two or three walls shared among their faces, for the wall forces of
// eq. 52 in 3-D (each particle's force on each face it has).
#include "fluid_emps/space_wall_terms.hpp"

namespace fsi::emps {

std::array<Vec3, max_faces3> split_corner_term(const Vec3& c, const SpaceHits& hits,
                                               std::size_t i) {
  std::array<Vec3, max_faces3> share;
  share.fill(Vec3::Zero());
  std::array<std::size_t, max_faces3> on{};
  std::size_t faces = 0;
  for (std::size_t k = 0; k < max_faces3; ++k)
    if (hits[k].triangle[i] >= 0) on[faces++] = k;
  if (faces == 0) return share;
  if (faces == 1) {
    share[on[0]] = c;
    return share;
  }
  Mat3 N = Mat3::Zero(); // the faces' normals as columns (the third zero with two faces)
  for (std::size_t a = 0; a < faces; ++a)
    N.col(static_cast<Eigen::Index>(a)) = hits[on[a]].n_wall[i];
  Vec3 coeff;
  if (faces == 3) {
    coeff = N.inverse() * c; // the corner's three normals span space (turns above 30 degrees)
  } else {
    const Eigen::Matrix<double, 3, 2> N2 = N.leftCols<2>();
    coeff.head<2>() = (N2.transpose() * N2).inverse() * (N2.transpose() * c);
    coeff[2] = 0.0;
  }
  Vec3 rest = c;
  for (std::size_t a = 0; a < faces; ++a) {
    share[on[a]] = coeff[static_cast<Eigen::Index>(a)] * N.col(static_cast<Eigen::Index>(a));
    rest -= share[on[a]];
  }
  share[on[0]] += rest;
  return share;
}

} // namespace fsi::emps
