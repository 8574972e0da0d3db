#pragma once
// The sections of a .msh file ($PhysicalNames, $Entities, $Nodes, $Elements; formats 4.1 and
// 2.2), each read into what the reader assembles the mesh from (private to structure_fem).
#include <array>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "gmsh_lexer.hpp"
#include "structure_fem/mesh.hpp"

namespace fsi::fem::gmsh {

struct RawLine {
  std::array<long, 3> nodes; // gmsh order: end, end, mid
  long tag, entity;
  int line;
  std::vector<long> physicals; // MSH 2.2: the element's own physical tag
};

/// What the sections of a file build up.
struct Parsed {
  std::map<std::pair<long, long>, std::string> physical_name;          // (dim, tag) -> name
  std::map<std::pair<long, long>, std::vector<long>> entity_physicals; // (dim, entity) -> tags
  std::map<long, int> node_index;
  Mesh mesh;
  MeshSourceLines lines;
  std::vector<RawLine> raw_lines;
  std::set<std::array<long, 3>> triangles; // sorted corners (MSH 2.2 repeats an element per group)
};

/// $PhysicalNames: the (dimension, tag) -> name map (both formats).
void read_physical_names(Lexer& lex, Parsed& p);
/// $Entities (4.1): the physical tags of each (dimension, entity).
void read_entities_41(Lexer& lex, Parsed& p);
/// $Nodes and $Elements of format 4.1 (ASCII or binary) and of ASCII 2.2: the nodes (in the plane
/// z = 0), the 6-node triangles and the 3-node lines.
void read_nodes_41(Lexer& lex, Parsed& p);
void read_elements_41(Lexer& lex, Parsed& p);
void read_nodes_22(Lexer& lex, Parsed& p);
void read_elements_22(Lexer& lex, Parsed& p);

} // namespace fsi::fem::gmsh
