// The sections of a .msh file read into Parsed: physical names, entities, nodes and elements of
// formats 4.1 and 2.2, each node and element checked as it is read (element type and order for
// the mesh's dimension, the plane z = 0 of a 2-D mesh, repeated and unknown tags).
#include "gmsh_sections.hpp"

#include <algorithm>
#include <cstdlib>

namespace fsi::fem::gmsh {

namespace {

/// The number of nodes of an element of Gmsh type `type` in a mesh of dimension `dim`; refuses
/// the element types that cannot be read, saying how to mesh the geometry instead.
int nodes_per_element(Lexer& lex, int dim, long type, long tag) {
  const std::string element = "element " + std::to_string(tag) + ": ";
  const std::string remedy = "mesh with gmsh -" + std::to_string(dim) + " -order 2";
  switch (type) {
  case 11:
    if (dim == 3) return 10; // 10-node tetrahedron
    lex.fail(element + "10-node tetrahedron (type 11): a 3-D mesh: read it as a 3-D solid (T10), "
                       "or mesh a surface at z = 0 with gmsh -2 -order 2");
  case 9:
    return 6; // 6-node triangle
  case 8:
    return 3; // 3-node line
  case 15:
    return 1; // point
  case 4:
    if (dim == 3)
      lex.fail(element +
               "4-node tetrahedron (type 4): wrong element order, need 10-node "
               "tetrahedra (type 11): " +
               remedy);
    [[fallthrough]];
  case 29:
    if (dim == 2) // 4-, 10- or 20-node tetrahedron in a 2-D read
      lex.fail(element + "tetrahedron (type " + std::to_string(type) +
               "): a 3-D mesh: read it as a 3-D solid (10-node tetrahedra, gmsh -3 -order 2), "
               "or mesh a surface at z = 0 with gmsh -2 -order 2");
    break;
  case 2:
    lex.fail(element +
             "3-node triangle (type 2): wrong element order, need second-order 6-node "
             "triangles (type 9): " +
             remedy);
  case 1:
    lex.fail(element +
             "2-node line (type 1): wrong element order, need 3-node lines (type 8): " + remedy);
  case 3:
  case 10:
  case 16:
    lex.fail(element + "quadrangle (type " + std::to_string(type) +
             "): need 6-node triangles (type 9): remove Recombine (Mesh.RecombineAll = 0) and " +
             remedy);
  case 21:
  case 23:
  case 25:
    lex.fail(element + "triangle of order 3 or more (type " + std::to_string(type) +
             "): need 6-node triangles (type 9): " + remedy);
  default:
    break;
  }
  lex.fail(element + "unsupported element type " + std::to_string(type) +
           (dim == 2 ? " (only 9, 8 and 15: a 2D mesh from gmsh -2 -order 2)"
                     : " (only 11, 9, 8 and 15: a 3D mesh from gmsh -3 -order 2)"));
}

/// The number of nodes of an element of Gmsh type `type` in a surface mesh (3-node triangles,
/// lines and points dropped); refuses what a surface of flat triangles cannot be made of.
int surface_nodes_per_element(Lexer& lex, long type, long tag) {
  const std::string element =
      "element " + std::to_string(tag) + " (type " + std::to_string(type) + "): ";
  switch (type) {
  case 2:
    return 3; // 3-node triangle
  case 1:
    return 2; // 2-node line
  case 15:
    return 1; // point
  case 8:
  case 9:
    lex.fail(element + "second-order element: need 3-node triangles (type 2): mesh with gmsh -2 "
                       "(order 1)");
  case 4:
  case 11:
  case 29:
    lex.fail(element + "tetrahedron: a volume mesh: need the surface only, gmsh -2");
  default:
    break;
  }
  lex.fail(element + "unsupported element type (only 2, 1 and 15: a surface mesh from gmsh -2)");
}

/// A node's z in a 2-D mesh: it must lie in the plane z = 0. The first node off it is kept and
/// refused after the elements, so that a 3-D mesh is named as such (its tetrahedra) first.
void check_planar(const Lexer& lex, Parsed& p, long tag, double z) {
  if (std::abs(z) > 1e-12 && p.off_plane.empty())
    p.off_plane = lex.where() + "node " + std::to_string(tag) + ": z = " + std::to_string(z) +
                  " m: the mesh must lie in the plane z = 0 (draw the geometry at z = 0)";
}

void add_node(Lexer& lex, Parsed& p, long tag, double x, double y, double z, int at) {
  if (p.dim == 2) check_planar(lex, p, tag, z);
  const auto [it, fresh] = p.node_index.emplace(tag, static_cast<int>(p.X.size()));
  if (!fresh)
    throw InputError(lex.binary()
                         ? lex.where() + "node " + std::to_string(tag) + ": node tag given twice"
                         : lex.path() + ":" + std::to_string(at) + ": node " + std::to_string(tag) +
                               ": node tag given twice");
  p.X.emplace_back(x, y, z);
  p.node_label.push_back(tag);
  if (!lex.binary()) p.node_line.push_back(at);
}

/// One element of type `type` with its nodes (gmsh tags) read by `node`: kept if it is a domain
/// or boundary element of the mesh's dimension.
template <class Next>
void add_element(Lexer& lex, Parsed& p, long type, long tag, long entity, int at, Next node,
                 std::vector<long> physicals = {}) {
  const int nn = p.surface ? surface_nodes_per_element(lex, type, tag)
                           : nodes_per_element(lex, p.dim, type, tag);
  std::vector<int> nodes;
  for (int k = 0; k < nn; ++k) {
    const long n = node();
    const auto it = p.node_index.find(n);
    if (it == p.node_index.end())
      lex.fail("element " + std::to_string(tag) + ": unknown node " + std::to_string(n));
    nodes.push_back(it->second);
  }
  if (type == p.domain_type()) {
    std::vector<int> corners(nodes.begin(), nodes.begin() + p.corners());
    std::sort(corners.begin(), corners.end());
    if (p.msh22 && !p.domain_corners.insert(corners).second) return; // the same, another group
  } else if (type != p.boundary_type()) {
    return; // points, and lines of a 3-D mesh or a surface
  }
  p.elements.push_back({type, tag, entity, at, std::move(nodes), std::move(physicals)});
}

/// The header of a msh 4.1 $Nodes or $Elements section (`what`: node or element): the number of
/// blocks (returned), the number of items and their smallest and largest tag.
long read_block_header(Lexer& lex, const std::string& what) {
  lex.begin_section();
  const long blocks = lex.size("the number of " + what + " blocks");
  lex.size("the number of " + what + "s");
  lex.size("the minimum " + what + " tag");
  lex.size("the maximum " + what + " tag");
  return blocks;
}

// A format 2.2 section: its record count, then each record's tag and the line it is on.
template <class Record>
void read_records_22(Lexer& lex, const char* count, const char* tag_name, Record record) {
  const long n = lex.integer(count);
  for (long i = 0; i < n; ++i) {
    const long tag = lex.integer(tag_name);
    record(tag, lex.line());
  }
}

} // namespace

void read_physical_names(Lexer& lex, Parsed& p) {
  const long n = lex.integer("the number of physical names");
  for (long i = 0; i < n; ++i) {
    const long dim = lex.integer("a physical dimension");
    const long tag = lex.integer("a physical tag");
    const std::string at = lex.where();
    const std::string rest = lex.rest_of_line();
    const auto a = rest.find('"'), b = rest.rfind('"');
    if (a == std::string::npos || b == a) throw InputError(at + "physical name must be quoted");
    p.physical_name[{dim, tag}] = rest.substr(a + 1, b - a - 1);
  }
  lex.expect("$EndPhysicalNames");
}

void read_entities_41(Lexer& lex, Parsed& p) {
  lex.begin_section();
  long count[4];
  for (auto& c : count) c = lex.size("the number of entities");
  for (long dim = 0; dim < 4; ++dim)
    for (long i = 0; i < count[dim]; ++i) {
      const long tag = lex.tag("an entity tag");
      for (int k = 0; k < (dim == 0 ? 3 : 6); ++k) lex.number("an entity bounding box");
      const long n_phys = lex.size("the number of physical tags");
      auto& phys = p.entity_physicals[{dim, tag}];
      for (long k = 0; k < n_phys; ++k) phys.push_back(std::abs(lex.tag("a physical tag")));
      if (dim > 0) {
        const long n_bound = lex.size("the number of bounding entities");
        for (long k = 0; k < n_bound; ++k) lex.tag("a bounding entity");
      }
    }
  lex.end_section("$EndEntities");
}

void read_nodes_41(Lexer& lex, Parsed& p) {
  const long blocks = read_block_header(lex, "node");
  for (long b = 0; b < blocks; ++b) {
    const long dim = lex.tag("a node block dimension");
    lex.tag("a node block entity");
    const long parametric = lex.tag("the parametric flag");
    const long n = lex.size("the number of nodes in the block");
    std::vector<long> tags;
    for (long i = 0; i < n; ++i) tags.push_back(lex.size("a node tag"));
    for (long i = 0; i < n; ++i) {
      if (!lex.binary()) lex.at_end(); // to the line of the coordinates
      const int at = lex.line();
      const double x = lex.number("a node coordinate"), y = lex.number("a node coordinate");
      const double z = lex.number("a node coordinate");
      for (long k = 0; parametric && k < dim; ++k) lex.number("a parametric coordinate");
      add_node(lex, p, tags[static_cast<std::size_t>(i)], x, y, z, at);
    }
  }
  lex.end_section("$EndNodes");
}

void read_elements_41(Lexer& lex, Parsed& p) {
  const long blocks = read_block_header(lex, "element");
  for (long b = 0; b < blocks; ++b) {
    lex.tag("an element block dimension");
    const long entity = lex.tag("an element block entity");
    const long type = lex.tag("an element type");
    const long n = lex.size("the number of elements in the block");
    for (long i = 0; i < n; ++i) {
      const long tag = lex.size("an element tag");
      add_element(lex, p, type, tag, entity, lex.line(),
                  [&] { return lex.size("an element node"); });
    }
  }
  lex.end_section("$EndElements");
}

void read_nodes_22(Lexer& lex, Parsed& p) {
  read_records_22(lex, "the number of nodes", "a node tag", [&](long tag, int at) {
    const double x = lex.real("a node coordinate"), y = lex.real("a node coordinate");
    add_node(lex, p, tag, x, y, lex.real("a node coordinate"), at);
  });
  lex.expect("$EndNodes");
}

void read_elements_22(Lexer& lex, Parsed& p) {
  read_records_22(lex, "the number of elements", "an element tag", [&](long tag, int at) {
    const long type = lex.integer("an element type");
    const long n_tags = lex.integer("the number of element tags");
    if (n_tags < 0) lex.fail("element " + std::to_string(tag) + ": negative number of tags");
    std::vector<long> tags;
    for (long k = 0; k < n_tags; ++k) tags.push_back(lex.integer("an element tag"));
    // Tag 1: the physical group (0: none), tag 2: the elementary entity.
    std::vector<long> physicals;
    if (!tags.empty() && tags[0] != 0) physicals.push_back(std::abs(tags[0]));
    add_element(
        lex, p, type, tag, tags.size() > 1 ? tags[1] : 0, at,
        [&] { return lex.integer("an element node"); }, physicals);
  });
  lex.expect("$EndElements");
}

} // namespace fsi::fem::gmsh
