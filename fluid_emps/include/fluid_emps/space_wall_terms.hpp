#pragma once
// The ERP wall terms of the 3-D EMPS step over triangle walls (Mitsume 2023, eqs. 20, 23-27, and
// what WallOptions adds), the counterpart of WallTerms: each a function of one particle i and one
// face k of the walls that act on it (face 0 the nearest triangle of eq. 18, faces 1 and 2 the
// other planes of a concave edge or corner, TriangleLocator::corner_faces). One file per term:
// space_wall_pnd.cpp, space_mirror_pressure.cpp, space_corner_mirror_pressure.cpp,
// space_corner_split.cpp (split_corner_term), space_mirror_viscous.cpp, space_wall_contact.cpp,
// space_wall_gap.cpp, space_convex_part.cpp (the convex edges' and corners' pieces),
// space_wall_pressure.cpp (the pressure terms summed), space_wall_forces.cpp (eq. 52's
// mapping). Not in 3-D yet: the viscous mirror's images behind two and three walls,
// WallContact::viscous and WallPressure::neighbours (the fluid refuses the last two).
#include "fluid_emps/options.hpp"
#include "fluid_emps/particles.hpp"
#include "geometry_erp/convex_wedge3.hpp"
#include "geometry_erp/triangle_locator.hpp"
#include "geometry_erp/wall_weight.hpp"
#include "particles/cell_grid.hpp"
#include "particles/kernels.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace fsi::emps {

/// Faces that can act on a particle in 3-D: the nearest wall, and two more at a concave corner.
inline constexpr std::size_t max_faces3 = 3;
using SpaceHits = std::array<erp::TriangleHits, max_faces3>;
/// The slots of a particle's wall force in 3-D (eq. 52): slot k < max_faces3 acting face k
/// (hits[k]), slot max_faces3 + q convex piece q (erp::ConvexFaces) on its seed triangle (the
/// pressure stage's, pressure_slots3), slot viscous_slot3 + k face k's viscous mirror term at the
/// viscous stage's hits (x^n).
inline constexpr std::size_t pressure_slots3 = max_faces3 + erp::ConvexFaces::max_pieces;
inline constexpr std::size_t viscous_slot3 = pressure_slots3;
inline constexpr std::size_t wall_slots3 = pressure_slots3 + max_faces3;
using WallShares3 = std::array<Vec3, pressure_slots3>;

/// The 3-D wall force of the last step in one slot of each particle (eq. 52: the pressure
/// mirror, the images behind two or three walls and the contact term, or a convex piece's term,
/// times V_i; or a face's viscous mirror term and approach viscosity, times rho V_i): the wall
/// receives -f at the point of `triangle` with barycentric coordinates `bary` (x_wall = bary[0]
/// x_a + bary[1] x_b + bary[2] x_c); triangle = -1 where the particle has no such face or piece.
/// f summed over the slots is what the walls add to the particle's momentum. The pieces' slots
/// are empty (size 0) without WallOptions::convex_corners, the viscous ones when no viscous wall
/// term runs (viscosity and approach viscosity 0). The viscous slots are filled at the viscous
/// stage: entry i there is the particle that was i then (a slot's entries need not follow a
/// reordering; loads sum over them).
struct TriangleForces {
  std::vector<int> triangle;
  std::vector<Vec3> bary, f;
  void resize(std::size_t n) {
    triangle.resize(n);
    bary.resize(n);
    f.resize(n);
  }
};
using WallForces3 = std::array<TriangleForces, wall_slots3>;

/// The images' term c behind two or three walls (SpaceWallTerms::corner_mirror_pressure) split
/// over the faces that make it: c = sum_k c_k n_k by least squares over the faces' normals, share
/// k = c_k n_k, the remainder (zero with three faces) on face 0; the shares sum to c to round-off.
std::array<Vec3, max_faces3> split_corner_term(const Vec3& c, const SpaceHits& hits, std::size_t i);

/// The sums of the viscous mirror term at x_i' (without the 2d/(lambda0 n0) factor).
struct MirrorViscous3 {
  Vec3 laplacian = Vec3::Zero(); ///< R <lap v>_i' (eq. 24)
  Vec3 approach = Vec3::Zero();  ///< the closing pairs across the wall (approach viscosity)
};

/// The wall terms over the fluid's particles, cell grid, hits and convex faces (filled with
/// WallOptions::convex_corners), which must outlive it.
class SpaceWallTerms {
public:
  SpaceWallTerms(const FluidOptions3& options, double n0, const Particles3& particles,
                 const particles::BasicCellGrid<3>& grid, const SpaceHits& hits,
                 const erp::ConvexFaces& convex);

  /// The convex pieces' part of particle i's wall terms (space_convex_part.cpp): the solid beside
  /// a convex edge or corner is the union of the half-spaces of the acting faces that seed no
  /// piece and the pieces (TriangleLocator::convex_faces); a face seeding a piece has no
  /// half-space, z or mirror of its own.
  struct ConvexPart {
    unsigned replaced = 0;    ///< bit k: acting face k seeds a piece
    erp::LatticeSum3 lattice; ///< the pieces' lattice in front of the other faces (eqs. 20, 10)
    /// eq. 10's geometric sum over that lattice reflected across the other faces (each, each pair,
    /// the three): where their mirrors find no fluid to image, the pieces being solid.
    Vec3 images = Vec3::Zero();
    /// Piece q's share of lattice.gradient + images, for its force (eq. 52): each term of the
    /// inclusion-exclusion shared equally among the pieces it intersects, so that a lattice
    /// point in t pieces gives 1/t to each (a point in one piece, all of it); the shares sum to
    /// the whole to round-off.
    std::array<Vec3, erp::ConvexFaces::max_pieces> share{Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
  };
  /// Empty without convex_corners, without pieces, or where a plane is not a box's.
  ConvexPart convex_part(std::size_t i) const;

  /// n*_i from the fluid part of pnd: z (eq. 20) summed over the acting faces, the lattice behind
  /// two or three walls counted once, the convex pieces' lattice added (space_wall_pnd.cpp).
  double pnd(std::size_t i, double fluid_pnd) const;
  /// (d/n0) R_ref <grad p>_i' (eqs. 25-26) on face k with p_i' = p_i (space_mirror_pressure.cpp).
  Vec3 mirror_pressure(std::size_t i, std::size_t k) const;
  /// The pieces' pressure term: virtual particles at p_i (eq. 26) on their lattice and its
  /// images, (d/n0) 2 p_i (lattice.gradient + images) (space_convex_part.cpp).
  Vec3 convex_pressure(std::size_t i, const ConvexPart& part) const;
  /// Piece q's part of it, (d/n0) 2 p_i share[q] (space_convex_part.cpp).
  Vec3 piece_pressure(std::size_t i, const ConvexPart& part, std::size_t q) const;
  /// The pressure term of the lattice behind two walls (each pair of acting faces not in
  /// `replaced`) and three (a corner), which no single face's mirror images: eqs. 25-26 across
  /// several planes (space_corner_mirror_pressure.cpp). Zero with fewer than two faces.
  Vec3 corner_mirror_pressure(std::size_t i, unsigned replaced = 0) const;
  /// Adds the wall part of <grad p>_i to grad (space_wall_pressure.cpp): each acting face's mirror
  /// pressure (unless it seeds a convex piece) and contact terms (eqs. 25-27), the images behind
  /// two or three faces once, the convex pieces' term; `shares` its share in each slot for eq. 52
  /// (wall_slots3: the images split over the faces by split_corner_term, each piece's term,
  /// ConvexPart::share, in its own slot).
  void add_pressure(std::size_t i, double dt, Vec3& grad, WallShares3& shares) const;
  /// Eq. 52's mapping: particle i's shares as the forces f = -V share in each slot, on the slot's
  /// triangle at its wall point (a face's x_wall, a piece's nearest point on its seed triangle;
  /// triangle -1 in an empty slot; the pieces' slots, sized only with convex_corners, left alone
  /// without) (space_wall_forces.cpp).
  void record_forces(std::size_t i, const WallShares3& shares, double V, WallForces3& forces) const;
  /// Face k's viscous wall force f on particle i in slot viscous_slot3 + k, at the hit of face k
  /// (the viscous stage's) (space_wall_forces.cpp).
  void record_viscous(std::size_t i, std::size_t k, const Vec3& f, WallForces3& forces) const;
  /// The viscous mirror sums on face k (eq. 24; `approach`: the approach viscosity's too)
  /// (space_mirror_viscous.cpp).
  MirrorViscous3 mirror_viscous(std::size_t i, std::size_t k, bool approach) const;
  /// The contact term on face k in the units of grad p: f_rep (eq. 27) and the wall-normal
  /// damping of WallContact::damped (space_wall_contact.cpp).
  Vec3 contact(std::size_t i, std::size_t k, double dt) const;
  /// The wall-gap step limit of particle i over its faces, given the step's last position
  /// correction dx (space_wall_gap.cpp).
  double gap_dt(std::size_t i, const Vec3& dx) const;

private:
  /// The turn between two faces as a share of a right angle (1 at 90 degrees), as in 2-D's
  /// concave_overlap: the weight of the lattice behind both.
  static double turn_share(const Vec3& n1, const Vec3& n2);
  /// The faces acting on i and not in `replaced` (hits_[on[k]], k < the count returned).
  std::size_t acting_faces(std::size_t i, std::array<std::size_t, max_faces3>& on,
                           unsigned replaced = 0) const;
  /// z of eq. 20 over the faces on[0 .. faces - 1]: each face's z(r), the lattice behind two and
  /// three of them counted once (space_wall_pnd.cpp).
  double faces_weight(std::size_t i, const std::array<std::size_t, max_faces3>& on,
                      std::size_t faces) const;
  bool behind(std::uint32_t j, const Vec3& x_wall, const Vec3& n_wall) const;
  /// f(j) for every binned particle in the cells that the ball of radius r_e around m touches
  /// (at most 2 x 2 x 2 of the grid's cells of side >= r_e, not the 27 of for_each_near).
  template <class F> void for_each_within(const Vec3& m, F&& f) const {
    std::array<int, 3> c0, c1;
    for (int a = 0; a < 3; ++a) {
      c0[static_cast<std::size_t>(a)] = grid_.cell(a, m[a] - r_e_);
      c1[static_cast<std::size_t>(a)] = grid_.cell(a, m[a] + r_e_);
    }
    const std::vector<std::uint32_t>& order = grid_.order();
    for (int z = c0[2]; z <= c1[2]; ++z)
      for (int y = c0[1]; y <= c1[1]; ++y) {
        const int row = z * grid_.cells(1) + y;
        for (std::uint32_t k = grid_.begin(c0[0], row), end = grid_.begin(c1[0] + 1, row); k < end;
             ++k)
          f(order[k]);
      }
  }
  Vec3 position(std::size_t i) const {
    return {p_.position[0][i], p_.position[1][i], p_.position[2][i]};
  }
  Vec3 velocity(std::size_t i) const {
    return {p_.velocity[0][i], p_.velocity[1][i], p_.velocity[2][i]};
  }

  WallOptions o_;
  double l0_, r_e_, re2_, rho_, c_, n0_;
  particles::MpsWeight w_e_; ///< w(r) of eq. 8 at r_e
  erp::WallWeightTable3 z_;  ///< z(r) of eq. 20 on the cubic lattice
  const Particles3& p_;
  const particles::BasicCellGrid<3>& grid_;
  const SpaceHits& hits_;
  const erp::ConvexFaces& convex_;
};

} // namespace fsi::emps
