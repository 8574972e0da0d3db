#pragma once
// The ERP wall terms of the EMPS step (Mitsume 2023, eqs. 20, 23-27, and what WallOptions adds),
// each a function of one particle i and one face k of the walls that act on it (geometry_erp's
// faces: k = 0 the nearest wall of eq. 18, k >= 1 the other faces of a concave corner). The step
// sums each term over the faces; a term's options are its own group of WallOptions. One file per
// term: wall_pnd.cpp, mirror_pressure.cpp, mirror_viscous.cpp, wall_contact.cpp, wall_gap.cpp.
#include "fluid_emps/options.hpp"
#include "fluid_emps/particles.hpp"
#include "geometry_erp/convex_corner.hpp"
#include "geometry_erp/wall_locator.hpp"
#include "geometry_erp/wall_set.hpp"
#include "geometry_erp/wall_weight.hpp"
#include "particles/cell_grid.hpp"
#include "particles/kernels.hpp"

#include <cstdint>

namespace fsi::emps {

inline constexpr double dim = 2.0; ///< d of eqs. 10-11, the number of dimensions

/// The sums of the viscous mirror term at x_i' (without the 2d/(lambda0 n0) factor).
struct MirrorViscous {
  Vec2 laplacian = Vec2::Zero(); ///< R <lap v>_i' (eq. 24)
  Vec2 approach = Vec2::Zero();  ///< the closing pairs across the wall (approach viscosity)
};

/// The wall terms over the fluid's particles, cell grid and wall hits, which must outlive it
/// (the fluid owns all four and keeps them current before each call).
class WallTerms {
public:
  WallTerms(const FluidOptions& options, double n0, const erp::WallSet& walls,
            const Particles& particles, const particles::CellGrid& grid, const erp::WallHits& hits);

  /// n*_i from the fluid part of pnd: the wall part z of eq. 20 summed over the faces, a
  /// corner's doubly counted lattice once, a convex corner's wedge (wall_pnd.cpp).
  double pnd(std::size_t i, double fluid_pnd) const;
  /// (d/n0) R_ref <grad p>_i' (eqs. 25-26) on face k with the mirror pressure p_i'
  /// (mirror_pressure.cpp).
  Vec2 mirror_pressure(std::size_t i, std::size_t k, double p_mirror) const;
  /// The viscous mirror sums on face k (eq. 24; `approach`: also the approach viscosity's)
  /// (mirror_viscous.cpp).
  MirrorViscous mirror_viscous(std::size_t i, std::size_t k, bool approach) const;
  /// The contact term on face k in the units of grad p: f_rep (eq. 27) and the wall-normal
  /// damping of WallContact::damped (wall_contact.cpp).
  Vec2 contact(std::size_t i, std::size_t k, double dt) const;
  /// The wall-gap step limit of particle i over its faces (WallOptions::gap_courant), given the
  /// step's last position correction (dx, dy) (wall_gap.cpp).
  double gap_dt(std::size_t i, double dx, double dy) const;

private:
  bool behind(std::uint32_t j, const Vec2& x_wall, const Vec2& n_wall) const;
  erp::ConvexPart convex_part(std::size_t i) const;

  WallOptions o_;
  double l0_, r_e_, re2_, rho_, c_, n0_;
  particles::MpsWeight w_e_; ///< w(r) of eq. 8 at r_e
  erp::WallWeightTable z_;   ///< z(r) of eq. 20
  const erp::WallSet& walls_;
  const Particles& p_;
  const particles::CellGrid& grid_;
  const erp::WallHits& hits_;
};

} // namespace fsi::emps
