// The 3-D set-up of a box of water in an open box tank: the lattice fill and the tank's dummies
// (the 3-D counterpart of fill_rectangle and of a polyline's dummies, wall_dummies.cpp).
#include "fluid_sph/sph_fluid.hpp"

#include "fsi/core/error.hpp"
#include "particles/lattice.hpp"

#include <cmath>

namespace fsi::sph {

using particles::lattice_layers;

std::vector<Vec3> fill_box(const Vec3& lo, const Vec3& hi, double dp) {
  if (!(dp > 0.0)) throw InputError("fluid_sph: fill_box needs dp > 0");
  return particles::lattice_box<3>(lo, hi, dp);
}

std::vector<WallPoint3> box_walls(const Vec3& lo, const Vec3& hi, double dp, int layers, int open,
                                  std::array<bool, 3> periodic) {
  if (!(dp > 0.0) || layers < 1 || !((hi - lo).minCoeff() > 0.0) || open < 0 || open > 2)
    throw InputError("fluid_sph: box_walls needs dp > 0, layers >= 1, hi > lo and open in 0-2");
  const double depth = layers * dp;
  // Lattice index ranges: `layers` beyond both faces, none beyond the open one nor along a
  // periodic axis (there the points stay inside [lo, hi], so none is behind those faces).
  long first[3], last[3];
  for (int c = 0; c < 3; ++c) {
    const bool wraps = periodic[static_cast<std::size_t>(c)];
    first[c] = wraps ? 0 : -layers;
    last[c] = lattice_layers(lo[c], hi[c], dp) + (c == open || wraps ? 0 : layers);
  }
  std::vector<WallPoint3> out;
  for (long k = first[2]; k < last[2]; ++k)
    for (long j = first[1]; j < last[1]; ++j)
      for (long i = first[0]; i < last[0]; ++i) {
        const Vec3 q = lo + dp * Vec3(static_cast<double>(i) + 0.5, static_cast<double>(j) + 0.5,
                                      static_cast<double>(k) + 0.5);
        // The nearest point of the tank's solid outside: q clamped into [lo, hi] (no lid).
        const Vec3 nearest = q.cwiseMax(lo).cwiseMin(hi);
        const Vec3 behind = nearest - q; // into the fluid, 0 along the axes inside the box
        const double dist = behind.norm();
        if (!(dist > 0.0) || dist >= depth) continue;
        // The normal: the sum of the faces' inward normals the point is behind, normalised.
        Vec3 n = Vec3::Zero();
        for (int c = 0; c < 3; ++c)
          if (behind[c] != 0.0) n[c] = behind[c] > 0.0 ? 1.0 : -1.0;
        n.normalize();
        out.push_back({q, n, 0, behind.dot(n), 0.0, 0.0});
      }
  return out;
}

} // namespace fsi::sph
