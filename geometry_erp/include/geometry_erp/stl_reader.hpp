#pragma once
// Triangle walls from an STL file (issue 43): ASCII ("solid ... endsolid") or binary (80-byte
// header, a uint32 facet count, 50 bytes per facet), as CAD tools and Gmsh write them.
//
// Orientation: each facet's vertices run counter-clockwise seen from the side its normal points
// to, the outward normal of the solid the surface bounds, which is the fluid's side
// (TriangleWallSet's convention): an obstacle's own surface, or a tank's inner wall facing its
// water. The vertices are merged where their coordinates are equal bit for bit (STL repeats them
// per facet), so neighbouring facets share nodes and edges.
//
// Checked, each refused with fsi::InputError `FILE:LINE: what` (ASCII) or `FILE: facet K: what`
// (binary; K from 1): malformed syntax, a non-finite coordinate, a degenerate facet (area
// <= 1e-12 of its longest edge squared, as TriangleWallSet), a stored normal pointing against
// the vertex order (n . ((b - a) x (c - a)) < 0; a zero normal is accepted), an edge shared by
// more than two facets, two facets traversing their shared edge the same way (one of them
// flipped), and a binary file whose size is not 84 + 50 n. Open edges (a tank open at the top)
// are allowed and counted.
#include "fsi/core/types.hpp"

#include <array>
#include <istream>
#include <string>
#include <vector>

namespace fsi::erp {

struct StlSurface {
  std::vector<Vec3> points;                  ///< merged vertices
  std::vector<std::array<int, 3>> triangles; ///< indices into points, in the file's order
  int open_edges = 0;                        ///< edges with one facet
};

/// One facet as read: the stored normal (zero: none, as a Gmsh triangle), the vertices in their
/// order, and where it is for messages (`FILE:LINE` or `FILE: facet K`).
struct SurfaceFacet {
  Vec3 n;
  std::array<Vec3, 3> v;
  std::string where;
};

/// Merges equal vertices and makes the checks above of every facet and edge (`WHERE: what`),
/// counts the open edges; shared by the STL reader and the Gmsh surfaces (fluid.tank_file).
StlSurface assemble_surface(const std::vector<SurfaceFacet>& facets, const std::string& file);

/// Reads an STL surface from `in`; `file` names it in messages. Binary if the stream does not
/// start with "solid" followed by white space, or if it does but its size is 84 + 50 n with n
/// the count at byte 80 (binary files whose header starts with "solid").
StlSurface read_stl(std::istream& in, const std::string& file);

/// Opens `path` and reads it; a file that cannot be opened is refused with `PATH: cannot open`.
StlSurface read_stl_file(const std::string& path);

} // namespace fsi::erp
