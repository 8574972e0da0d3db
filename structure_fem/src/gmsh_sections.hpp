#pragma once
// The sections of a .msh file ($PhysicalNames, $Entities, $Nodes, $Elements; formats 4.1 and
// 2.2), each read into what the readers assemble a T6 or a T10 mesh from (private to
// structure_fem).
#include <fstream>
#include <istream>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "fsi/core/types.hpp"
#include "gmsh_lexer.hpp"

namespace fsi::fem::gmsh {

/// An element kept from $Elements: a domain element (6-node triangle in 2-D, 10-node tetrahedron
/// in 3-D) or a boundary one (3-node line in 2-D, 6-node triangle in 3-D).
struct RawElement {
  long type, tag, entity;
  int line;                    // the line it is on (ASCII files)
  std::vector<int> nodes;      // indices into Parsed::X, in Gmsh's node order
  std::vector<long> physicals; // MSH 2.2: the element's own physical tag
};

/// What the sections of a file build up.
struct Parsed {
  int dim = 2;          // of the mesh read: 2 (T6, nodes in the plane z = 0) or 3 (T10)
  bool surface = false; // dim 3: a surface of 3-node triangles (gmsh -2 on a 3-D geometry)
  std::string path;
  bool binary = false, msh22 = false;
  std::map<std::pair<long, long>, std::string> physical_name;          // (dim, tag) -> name
  std::map<std::pair<long, long>, std::vector<long>> entity_physicals; // (dim, entity) -> tags
  std::map<long, int> node_index;
  std::vector<Vec3> X;
  std::vector<long> node_label;
  std::vector<int> node_line; // ASCII files only
  std::vector<RawElement> elements;
  std::set<std::vector<int>> domain_corners; // sorted (MSH 2.2 repeats an element per group)
  std::string off_plane; // 2-D: the refusal of the first node off z = 0 (empty: none)

  /// Gmsh's element type of the domain (9: 6-node triangle, 11: 10-node tetrahedron, a
  /// surface's 2: 3-node triangle).
  long domain_type() const { return surface ? 2 : dim == 2 ? 9 : 11; }
  /// Gmsh's element type of the boundary (8: 3-node line, 9: 6-node triangle; a surface: none).
  long boundary_type() const { return surface ? -1 : dim == 2 ? 8 : 9; }
  /// The corners of a domain element.
  int corners() const { return surface ? 3 : dim + 1; }
  /// "PATH:LINE: " for an ASCII file, "PATH: " for a binary one.
  std::string at(int line) const {
    return binary ? path + ": " : path + ":" + std::to_string(line) + ": ";
  }
  /// The physical tags of a boundary element (its own in 2.2, its entity's in 4.1: null when the
  /// entity is not in $Entities).
  const std::vector<long>* physicals(const RawElement& el) const;
  /// The name of physical group `tag` of the boundary's dimension (the tag if it has none).
  std::string boundary_name(long tag) const;
};

/// `path` opened for reading; throws InputError when it is no regular file or cannot be opened.
std::ifstream open_mesh_file(const std::string& path);
/// The whole file: the format line, the sections in file order, the required physical groups;
/// `surface` (dim 3): 3-node triangles.
Parsed parse(std::istream& in, const std::string& path, int dim,
             const std::vector<std::string>& required_groups, bool surface = false);

/// $PhysicalNames: the (dimension, tag) -> name map (both formats).
void read_physical_names(Lexer& lex, Parsed& p);
/// $Entities (4.1): the physical tags of each (dimension, entity).
void read_entities_41(Lexer& lex, Parsed& p);
/// $Nodes and $Elements of format 4.1 (ASCII or binary) and of ASCII 2.2: the nodes (in 2-D in
/// the plane z = 0), the domain and boundary elements (points and, in 3-D, lines dropped).
void read_nodes_41(Lexer& lex, Parsed& p);
void read_elements_41(Lexer& lex, Parsed& p);
void read_nodes_22(Lexer& lex, Parsed& p);
void read_elements_22(Lexer& lex, Parsed& p);

} // namespace fsi::fem::gmsh
