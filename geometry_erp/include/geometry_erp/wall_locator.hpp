#pragma once
// Nearest wall point for many particles at once (eqs. 18-19).
//
// For each particle within r_e of some segment: the nearest point x_wall over all segments, the
// distance r = |x - x_wall|, the unit normal n_wall from the wall to the particle (eq. 19), the
// segment and the local coordinate t in [0, 1] on it (x_wall = (1 - t) x_a + t x_b), and the wall
// velocity and acceleration interpolated linearly along the segment.
//
// Normal and crossing: the "fluid normal" at x_wall is the segment's left normal, or the node
// pseudo-normal (WallSet::node_normal) when x_wall is a node (t = 0 or 1).
// - r <= on_wall_tolerance * r_e: the particle is on the wall; n_wall is the fluid normal and the
//   particle is not crossed.
// - otherwise n_wall = (x - x_wall) / r, and the particle is crossed (on the solid side of its
//   nearest wall) when n_wall . fluid normal < 0 — except beyond the free end of an open
//   polyline (WallSet::open_end), where there is no solid. Crossed particles are reported, never
//   fixed.
// Equally near segments are resolved towards the lower segment index, so results do not depend
// on the back-end or the thread count.
//
// Corner faces (optional, an extension of eq. 18 for concave corners): near a corner the nearest
// wall alone leaves the other wall's half of the support empty, and particles leak into the
// corner. With set_corner_faces(true) each hit also reports, as face k = 1, 2, ... < max_faces,
// the nearest OTHER face within r_e: a segment whose nearest point is strictly inside it (not at
// a node, so the next segment of the same polyline never counts), not one of faces 0..k-1, with
// the particle on its fluid side, and whose normal differs from each of faces 0..k-1's n_wall by
// more than 30 degrees (so the gentle turns of a curved wall never count).
#include "fsi/core/types.hpp"
#include "geometry_erp/query_points.hpp"
#include "geometry_erp/wall_set.hpp"

#include <array>
#include <memory>
#include <span>
#include <vector>

namespace fsi::erp {

/// Faces a particle's wall terms can take: the nearest wall (eq. 18) and, at a concave corner of
/// the plane, one other face.
inline constexpr std::size_t max_faces = 2;

/// One face of every particle (struct-of-arrays): the segment (-1: none), the local coordinate t
/// of x_wall on it, the distance r, the wall point, the normal from the wall to the particle and
/// the wall velocity there.
struct FaceHits {
  std::vector<int> segment;
  std::vector<double> t, r;
  std::vector<Vec2> x_wall, n_wall, v_wall;
  void resize(std::size_t n);
};

/// Query results, one entry per particle. face[0] is the nearest wall; for a particle with no
/// wall within r_e, its segment = -1, r = +inf, crossed = 0 and the other fields are left
/// unchanged. face[k >= 1] are the corner faces (see above), segment = -1 where there is none or
/// the query did not ask; a_wall and crossed belong to face[0].
struct WallHits {
  std::array<FaceHits, max_faces> face;
  std::vector<Vec2> a_wall;
  std::vector<unsigned char> crossed;
  /// Grows every array to n (no allocation once warmed up to the largest n).
  void resize(std::size_t n);
  std::size_t size() const { return face[0].segment.size(); }
};

/// Distance below which a particle counts as on the wall, as a fraction of r_e.
inline constexpr double on_wall_tolerance = 1e-10;

/// A corner face must turn by more than this from the faces before it: cos 30 degrees.
inline constexpr double corner_face_max_cos = 0.8660254037844387;

enum class LocatorKind { grid, aabb_tree };

/// The default back-end (docs/geometry_erp.md gives the measurements behind the choice).
inline constexpr LocatorKind default_locator = LocatorKind::grid;

/// A spatial index over the segments of one WallSet, which must outlive it. Call update() after
/// nodes move or segments are added, before the next query. Queries are const, run through
/// fsi::parallel_for_balanced and do not allocate once `hits` has the particle count.
class WallLocator {
public:
  virtual ~WallLocator() = default;
  /// Rebuilds the index for the current node positions.
  virtual void update() = 0;
  void query(std::span<const Vec2> x, WallHits& hits) const { locate(QueryPoints(x), hits); }
  /// Same with particle coordinates as separate arrays, x.size() == y.size().
  void query(std::span<const double> x, std::span<const double> y, WallHits& hits) const {
    locate(QueryPoints(x, y), hits);
  }

  /// Also report the other faces of concave corners (off by default).
  void set_corner_faces(bool on) { corner_faces_ = on; }
  bool corner_faces() const { return corner_faces_; }
  double r_e() const { return r_e_; }
  const WallSet& walls() const { return *walls_; }

protected:
  WallLocator(const WallSet& walls, double r_e) : walls_(&walls), r_e_(r_e) {}
  /// The back-end's query: the nearest segment within r_e of every point.
  virtual void locate(const QueryPoints& points, WallHits& hits) const = 0;
  const WallSet* walls_;
  double r_e_;
  bool corner_faces_ = false;
};

/// A locator of the given kind, already updated.
std::unique_ptr<WallLocator> make_wall_locator(const WallSet& walls, double r_e,
                                               LocatorKind kind = default_locator);

} // namespace fsi::erp
