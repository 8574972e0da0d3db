#pragma once
// Nearest triangle wall point for many particles at once (eqs. 18-19 over a TriangleWallSet), the
// 3-D counterpart of WallLocator's grid back-end.
//
// For each particle within r_e of some triangle: the triangle, the nearest point x_wall on it
// (Ericson, Real-Time Collision Detection, sec. 5.1.5) with its barycentric coordinates and the
// feature (vertex, edge or face) it lies on, the distance r = |x - x_wall|, the unit normal
// n_wall = (x - x_wall) / r (eq. 19), and the wall velocity and acceleration interpolated
// barycentrically.
// - r <= on_wall_tolerance * r_e: the particle is on the wall; n_wall is the feature's
//   pseudo-normal (TriangleWallSet::pseudo_normal) and it is not crossed.
// - otherwise it is crossed when (x - x_wall) . pseudo-normal < 0 (Baerentzen & Aanaes 2005) —
//   except when x_wall is on an open edge or vertex (TriangleWallSet::open): no solid there.
// Equally near triangles are resolved towards the lower index, so results do not depend on the
// thread count.
//
// Search: triangles are binned into cubic cells of side h >= r_e (every cell their bounding box
// overlaps: particles::BoxGrid); a particle checks its own cell, then each of the 26 neighbours
// whose box is not farther than the best triangle so far.
//
// Concave edges and corners (corner_faces): as in 2-D (WallLocator::set_corner_faces), each hit
// also takes, as faces k = 1, 2, the nearest OTHER plane within r_e: a triangle whose plane the
// particle is in front of (signed distance > on_wall_tolerance r_e) with its foot, the projection
// onto that plane, inside the triangle (edges included, so a face split into triangles keeps its
// foot on the shared edges), and whose normal turns by more than 30 degrees from each face before
// it (so the pieces of one plane and the gentle turns of a curved wall never count). Beside a
// convex edge the foot falls outside the other face's triangles, so only concave ones count.
//
// Convex edges and corners (convex_faces): beside a box obstacle's edge a face's half-space is not
// the solid. Each particle gets up to three convex pieces, each the intersection of the
// half-spaces behind its planes: plane 0 its seed triangle's, then, in order of distance, the
// nearest other triangles within r_e whose normal turns by more than 30 degrees from the seed's
// and from each one taken before (the opposite face of a box thinner than r_e included), lying
// behind the seed's plane while the seed lies behind theirs (both to on_wall_tolerance r_e): the
// other faces of a convex edge, corner or small box. A concave edge's other face is in front of
// the plane, a coplanar piece does not turn. Seeds: every acting face (the nearest triangle and the
// corner faces above), a piece kept where it has a convex face; then the nearest triangle within
// r_e that the particle is in front of, turned by more than 30 degrees from every plane taken so
// far and wholly on or in front of every acting face's plane: a solid standing on an acting
// face, whose edge is near and none of whose faces acts (the foot of a box's vertical edge on the
// floor). A seed of its own without a convex face ends the search.
// Whether any pair of triangles can be such faces is found once per update() (has_convex_edges):
// a tank without convex edges skips the per-point search.
//
// These are new types rather than WallHits<D>: the 2-D record carries one segment coordinate t
// and the corner faces; a triangle needs barycentric coordinates and a feature.
#include "fsi/core/types.hpp"
#include "geometry_erp/query_points.hpp"
#include "geometry_erp/triangle_wall_set.hpp"
#include "particles/box_grid.hpp"

#include <algorithm>
#include <array>
#include <span>
#include <vector>

namespace fsi::erp {

/// Query results, one entry per particle (struct-of-arrays). A particle with no triangle within
/// r_e has triangle = -1, r = +inf, crossed = 0 and the other fields left unchanged.
struct TriangleHits {
  std::vector<int> triangle;
  std::vector<TriangleFeature> feature;
  std::vector<Vec3> bary; ///< x_wall = bary[0] x_a + bary[1] x_b + bary[2] x_c
  std::vector<double> r;
  std::vector<Vec3> x_wall, n_wall, v_wall, a_wall;
  std::vector<unsigned char> crossed;
  /// Grows every array to n (no allocation once warmed up to the largest n).
  void resize(std::size_t n);
  std::size_t size() const { return triangle.size(); }
};

/// The convex pieces beside each particle (TriangleLocator::convex_faces), their planes in one
/// list: piece q has planes begin(q) .. end[q] - 1, the first its seed's, the others its convex
/// faces'; unit normal n (into the fluid) and the particle's signed distance s from the plane
/// (> 0 in front). face[q]: the acting face k (faces[k] of the query) that seeds it, -1 for a seed
/// of its own; seed[q] its seed triangle and bary[q] the barycentric coordinates on it of the
/// particle's nearest point there (an acting face's x_wall), where eq. 52 records the piece's
/// force.
struct ConvexFaces {
  static constexpr std::size_t max_pieces = 3, max_planes = 8;
  std::vector<unsigned char> pieces;
  std::array<std::vector<signed char>, max_pieces> face;
  std::array<std::vector<int>, max_pieces> seed;
  std::array<std::vector<Vec3>, max_pieces> bary;
  std::array<std::vector<unsigned char>, max_pieces> end;
  std::array<std::vector<Vec3>, max_planes> n;
  std::array<std::vector<double>, max_planes> s;
  std::size_t begin(std::size_t q, std::size_t i) const { return q == 0 ? 0 : end[q - 1][i]; }
  void resize(std::size_t n_points);
};

/// The triangle with its node positions as of TriangleLocator::update().
struct TriangleGeometry {
  Vec3 a, b, c;
  int id;
};

/// A uniform grid over the triangles of one TriangleWallSet, which must outlive it. After nodes
/// move: TriangleWallSet::update(), then update() here, before the next query. Queries are const,
/// run through fsi::parallel_for_balanced and do not allocate once `hits` has the particle count.
class TriangleLocator {
public:
  TriangleLocator(const TriangleWallSet& walls, double r_e);
  /// Rebuilds the grid for the current node positions, and has_convex_edges().
  void update();
  void query(std::span<const Vec3> x, TriangleHits& hits) const { locate(QueryPoints3(x), hits); }
  /// Same with the coordinates as separate arrays of one size.
  void query(std::span<const double> x, std::span<const double> y, std::span<const double> z,
             TriangleHits& hits) const {
    locate(QueryPoints3(x, y, z), hits);
  }
  /// The corner faces (see above) into faces[1 ..], faces[0] being the points' nearest-triangle
  /// hits from query(); a face k has triangle = -1 where there is none, feature = face, crossed =
  /// 0, a_wall interpolated like v_wall.
  void corner_faces(std::span<const double> x, std::span<const double> y, std::span<const double> z,
                    std::span<TriangleHits> faces) const;
  /// The convex pieces (see above) of each point, `faces` being its acting faces from query()
  /// and corner_faces() (faces[k].triangle = -1 where there is none).
  void convex_faces(std::span<const double> x, std::span<const double> y, std::span<const double> z,
                    std::span<const TriangleHits> faces, ConvexFaces& convex) const;
  /// Some pair of triangles within 2 r_e of each other makes a convex edge or corner (as
  /// convex_faces takes them); without one convex_faces finds no piece at any point.
  bool has_convex_edges() const { return has_convex_edges_; }
  double r_e() const { return r_e_; }
  double cell_size() const { return grid_.cell_size(); }
  const TriangleWallSet& walls() const { return *walls_; }

private:
  void locate(const QueryPoints3& points, TriangleHits& hits) const;
  /// Triangle t with its node positions now.
  TriangleGeometry geometry(std::size_t t) const;
  /// Whether some pair of triangles makes a convex edge or corner (the search of update()).
  bool find_convex_edge() const;
  /// The nearest corner face of point p that turns from each of `normals` by more than 30 degrees.
  void corner_face(const Vec3& p, std::span<const Vec3> normals, TriangleHits& face,
                   std::size_t i) const;
  /// Appends to convex's planes of point i the piece seeded by triangle t0 (plane 0, then its
  /// convex faces) and returns the new end (`m` + 1 + its convex faces, at most max_planes).
  std::size_t convex_piece(const Vec3& p, int t0, ConvexFaces& convex, std::size_t i,
                           std::size_t m) const;

  /// f(g) for the triangles binned in the 3 x 3 x 3 cells around p (every triangle within r_e);
  /// a triangle spanning several cells comes once per cell.
  template <class F> void for_each_near(const Vec3& p, F&& f) const;

  const TriangleWallSet* walls_;
  double r_e_;
  std::vector<particles::Box3d> boxes_;         // the triangles' bounding boxes
  particles::BoxGrid grid_;                     // the triangles of each cell
  std::vector<TriangleGeometry> cell_triangle_; // grid_.entries() with their geometry
  bool has_convex_edges_ = true;
};

template <class F> void TriangleLocator::for_each_near(const Vec3& p, F&& f) const {
  const Vec3& origin = grid_.origin();
  const auto& dims = grid_.dims();
  const Vec3 c = ((p - origin) / grid_.cell_size()).array().floor();
  if (!((c.array() >= -1.0).all() && c[0] <= dims[0] && c[1] <= dims[1] && c[2] <= dims[2])) return;
  const std::array<int, 3> ci{static_cast<int>(c[0]), static_cast<int>(c[1]),
                              static_cast<int>(c[2])};
  for (int k = std::max(ci[2] - 1, 0); k <= std::min(ci[2] + 1, dims[2] - 1); ++k)
    for (int j = std::max(ci[1] - 1, 0); j <= std::min(ci[1] + 1, dims[1] - 1); ++j)
      for (int i = std::max(ci[0] - 1, 0); i <= std::min(ci[0] + 1, dims[0] - 1); ++i) {
        const std::size_t cell = grid_.cell(i, j, k);
        for (int q = grid_.begin(cell); q < grid_.begin(cell + 1); ++q)
          f(cell_triangle_[static_cast<std::size_t>(q)]);
      }
}

} // namespace fsi::erp
