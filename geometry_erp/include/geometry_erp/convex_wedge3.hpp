#pragma once
// The solid's lattice beside a 3-D convex edge or corner (a box obstacle's): the virtual cubic
// lattice of eqs. 20 and 25 inside an intersection of half-spaces, in place of the one half-space
// that z(r) and the nearest face's mirror assume.
#include "fsi/core/types.hpp"
#include "particles/kernels.hpp"

#include <optional>
#include <span>

namespace fsi::erp {

/// The half-space of points y with (y - x_i) . n < -s, seen from a particle at x_i: its plane
/// lies s in front of the points behind it (s > 0: the particle is outside it, at distance s).
/// A face with unit normal n (into the fluid) at signed distance d from the particle bounds
/// the solid {n, d} and the fluid side {-n, -d}.
struct HalfSpace3 {
  Vec3 n;
  double s;
};

/// Eq. 9's weight sum and eq. 10's geometric sum over a set of lattice points x_k: sum w and
/// sum (x_k - x_i) w / |x_k - x_i|^2.
struct LatticeSum3 {
  double weight = 0.0;
  Vec3 gradient = Vec3::Zero();
};

/// Both sums over the virtual cubic lattice (spacing l0, aligned with the particle, its planes
/// halfway between rows as z(r)'s) inside the intersection of the half-spaces, whose normals must
/// be parallel or perpendicular to each other (a box's faces): along each of at most three axes
/// the rows between the bounds, each bound the particle is inside of taken as the free rows less
/// the half-line beyond it, so the particle's own row is its own as in z(r); exact on the lattice.
/// Zero for an empty intersection, nullopt for planes that are not a box's.
std::optional<LatticeSum3> region_lattice_sum3(std::span<const HalfSpace3> region, double l0,
                                               double r_e, const particles::MpsWeight& w);

} // namespace fsi::erp
