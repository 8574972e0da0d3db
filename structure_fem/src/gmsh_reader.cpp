#include "structure_fem/gmsh_reader.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <utility>

#include "fsi/core/error.hpp"

namespace fsi::fem {

namespace {

/// Largest integer accepted anywhere (tags, counts): far beyond any real mesh, small enough that
/// no count or sign flip overflows.
constexpr long kLargest = 1L << 40;

/// Whitespace-separated tokens of a text file, with the line each came from.
class Lexer {
public:
  Lexer(std::istream& in, std::string path) : path_(std::move(path)) {
    for (std::string line; std::getline(in, line);) lines_.push_back(line);
  }
  int line() const { return static_cast<int>(line_) + 1; }
  const std::string& path() const { return path_; }
  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(path_ + ":" + std::to_string(line()) + ": " + what);
  }
  std::string token(const std::string& what) {
    while (line_ < lines_.size()) {
      const std::string& s = lines_[line_];
      while (pos_ < s.size() && std::isspace(static_cast<unsigned char>(s[pos_]))) ++pos_;
      if (pos_ < s.size()) {
        const std::size_t start = pos_;
        while (pos_ < s.size() && !std::isspace(static_cast<unsigned char>(s[pos_]))) ++pos_;
        return s.substr(start, pos_ - start);
      }
      ++line_, pos_ = 0;
    }
    throw InputError(path_ + ":" + std::to_string(lines_.size()) +
                     ": unexpected end of file while reading " + what + " (truncated file?)");
  }
  long integer(const std::string& what) {
    const std::string t = token(what);
    long v = 0;
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (ec != std::errc() || end != t.data() + t.size())
      fail("expected an integer for " + what + ", found \"" + t + "\"");
    if (v < -kLargest || v > kLargest) fail(what + " " + t + " is out of range");
    return v;
  }
  double real(const std::string& what) {
    const std::string t = token(what);
    try {
      std::size_t used = 0;
      const double v = std::stod(t, &used);
      if (used == t.size() && std::isfinite(v)) return v;
    } catch (const std::exception&) {
    }
    fail("expected a finite number for " + what + ", found \"" + t + "\"");
  }
  /// The unread rest of the current line (used for quoted names).
  std::string rest_of_line() {
    std::string r = line_ < lines_.size() ? lines_[line_].substr(pos_) : std::string();
    ++line_, pos_ = 0;
    return r;
  }
  void expect(const std::string& keyword) {
    const std::string t = token(keyword);
    if (t != keyword) fail("expected " + keyword + ", found \"" + t + "\"");
  }

private:
  std::string path_;
  std::vector<std::string> lines_;
  std::size_t line_ = 0, pos_ = 0;
};

int nodes_per_element(Lexer& lex, long type, long tag) {
  switch (type) {
  case 9:
    return 6; // 6-node triangle
  case 8:
    return 3; // 3-node line
  case 15:
    return 1; // point
  case 2:
    lex.fail("element " + std::to_string(tag) +
             ": 3-node triangle (type 2): wrong element order, need second-order 6-node "
             "triangles (type 9, gmsh -order 2)");
  case 1:
    lex.fail("element " + std::to_string(tag) +
             ": 2-node line (type 1): wrong element order, need 3-node lines (type 8)");
  default:
    lex.fail("element " + std::to_string(tag) + ": unsupported element type " +
             std::to_string(type) + " (only 9, 8 and 15)");
  }
}

struct RawLine {
  std::array<long, 3> nodes; // gmsh order: end, end, mid
  long tag, entity;
  int line;
};

} // namespace

Mesh read_gmsh(const std::string& path, const std::vector<std::string>& required_groups) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open the mesh file");
  return read_gmsh(in, path, required_groups);
}

Mesh read_gmsh(std::istream& in, const std::string& path,
               const std::vector<std::string>& required_groups) {
  Lexer lex(in, path);
  lex.expect("$MeshFormat");
  const std::string version = lex.token("the format version");
  if (version != "4.1") lex.fail("unsupported .msh version " + version + ", need 4.1");
  if (lex.integer("the file type") != 0)
    lex.fail("binary .msh files are not supported, need ASCII");
  lex.integer("the data size");
  lex.expect("$EndMeshFormat");

  std::map<std::pair<long, long>, std::string> physical_name;          // (dim, tag) -> name
  std::map<std::pair<long, long>, std::vector<long>> entity_physicals; // (dim, entity) -> tags
  std::map<long, int> node_index;
  Mesh mesh;
  mesh.source = path;
  MeshSourceLines lines;
  std::vector<RawLine> raw_lines;
  bool have_nodes = false, have_elements = false;

  for (;;) {
    std::string section;
    try {
      section = lex.token("a section");
    } catch (const InputError&) {
      break; // end of file between sections
    }
    if (section == "$PhysicalNames") {
      const long n = lex.integer("the number of physical names");
      for (long i = 0; i < n; ++i) {
        const long dim = lex.integer("a physical dimension");
        const long tag = lex.integer("a physical tag");
        const int at = lex.line();
        const std::string rest = lex.rest_of_line();
        const auto a = rest.find('"'), b = rest.rfind('"');
        if (a == std::string::npos || b == a)
          throw InputError(path + ":" + std::to_string(at) + ": physical name must be quoted");
        physical_name[{dim, tag}] = rest.substr(a + 1, b - a - 1);
      }
      lex.expect("$EndPhysicalNames");
    } else if (section == "$Entities") {
      long count[4];
      for (auto& c : count) c = lex.integer("the number of entities");
      for (long dim = 0; dim < 4; ++dim)
        for (long i = 0; i < count[dim]; ++i) {
          const long tag = lex.integer("an entity tag");
          for (int k = 0; k < (dim == 0 ? 3 : 6); ++k) lex.real("an entity bounding box");
          const long n_phys = lex.integer("the number of physical tags");
          auto& phys = entity_physicals[{dim, tag}];
          for (long k = 0; k < n_phys; ++k) phys.push_back(std::abs(lex.integer("a physical tag")));
          if (dim > 0) {
            const long n_bound = lex.integer("the number of bounding entities");
            for (long k = 0; k < n_bound; ++k) lex.integer("a bounding entity");
          }
        }
      lex.expect("$EndEntities");
    } else if (section == "$Nodes") {
      have_nodes = true;
      const long blocks = lex.integer("the number of node blocks");
      lex.integer("the number of nodes");
      lex.integer("the minimum node tag");
      lex.integer("the maximum node tag");
      for (long b = 0; b < blocks; ++b) {
        const long dim = lex.integer("a node block dimension");
        lex.integer("a node block entity");
        const long parametric = lex.integer("the parametric flag");
        const long n = lex.integer("the number of nodes in the block");
        std::vector<long> tags;
        for (long i = 0; i < n; ++i) tags.push_back(lex.integer("a node tag"));
        for (long i = 0; i < n; ++i) {
          const int at = lex.line();
          const double x = lex.real("a node coordinate"), y = lex.real("a node coordinate");
          lex.real("a node coordinate");
          for (long k = 0; parametric && k < dim; ++k) lex.real("a parametric coordinate");
          const auto [it, fresh] = node_index.emplace(tags[static_cast<std::size_t>(i)],
                                                      static_cast<int>(mesh.X.size()));
          if (!fresh)
            throw InputError(path + ":" + std::to_string(at) + ": node " +
                             std::to_string(it->first) + ": node tag given twice");
          mesh.X.emplace_back(x, y);
          mesh.node_label.push_back(it->first);
          lines.node_line.push_back(at);
        }
      }
      lex.expect("$EndNodes");
    } else if (section == "$Elements") {
      have_elements = true;
      const long blocks = lex.integer("the number of element blocks");
      lex.integer("the number of elements");
      lex.integer("the minimum element tag");
      lex.integer("the maximum element tag");
      for (long b = 0; b < blocks; ++b) {
        lex.integer("an element block dimension");
        const long entity = lex.integer("an element block entity");
        const long type = lex.integer("an element type");
        const long n = lex.integer("the number of elements in the block");
        for (long i = 0; i < n; ++i) {
          const long tag = lex.integer("an element tag");
          const int at = lex.line();
          const int nn = nodes_per_element(lex, type, tag);
          std::array<int, 6> el{};
          std::array<long, 3> ln{};
          for (int k = 0; k < nn; ++k) {
            const long node = lex.integer("an element node");
            const auto it = node_index.find(node);
            if (it == node_index.end())
              lex.fail("element " + std::to_string(tag) + ": unknown node " + std::to_string(node));
            if (type == 9) el[static_cast<std::size_t>(k)] = it->second;
            if (type == 8) ln[static_cast<std::size_t>(k)] = node;
          }
          if (type == 9) {
            mesh.elements.push_back(el);
            mesh.element_label.push_back(tag);
            lines.element_line.push_back(at);
          } else if (type == 8) {
            raw_lines.push_back({ln, tag, entity, at});
          }
        }
      }
      lex.expect("$EndElements");
    } else if (section.size() > 1 && section[0] == '$') {
      const std::string end = "$End" + section.substr(1);
      while (lex.token(end) != end) {
      }
    } else {
      lex.fail("expected a section ($Name), found \"" + section + "\"");
    }
  }
  if (!have_nodes) throw InputError(path + ": no $Nodes section");
  if (!have_elements) throw InputError(path + ": no $Elements section");

  std::set<std::string> names;
  for (const auto& [key, name] : physical_name) names.insert(name);
  for (const auto& g : required_groups)
    if (!names.count(g))
      throw InputError(path + ": missing physical group \"" + g + "\" (the file names: " + [&] {
        std::string all;
        for (const auto& n : names) all += (all.empty() ? "" : ", ") + n;
        return all.empty() ? std::string("none") : all;
      }() + ")");

  // 3-node lines become edges (corner, mid, corner), turned so that their triangle is on the left.
  std::map<std::pair<int, int>, int> side_of; // directed corner pair of a triangle side
  for (const auto& el : mesh.elements)
    for (int s = 0; s < 3; ++s)
      side_of[{el[static_cast<std::size_t>(s)], el[static_cast<std::size_t>((s + 1) % 3)]}] = 1;
  for (const auto& raw : raw_lines) {
    const auto it = entity_physicals.find({1, raw.entity});
    if (it == entity_physicals.end()) continue;
    int a = node_index.at(raw.nodes[0]), b = node_index.at(raw.nodes[1]);
    const int m = node_index.at(raw.nodes[2]);
    if (!side_of.count({a, b})) std::swap(a, b);
    if (!side_of.count({a, b}))
      throw InputError(path + ":" + std::to_string(raw.line) + ": line element " +
                       std::to_string(raw.tag) + " is not the side of any triangle");
    for (long phys : it->second) {
      const auto name = physical_name.find({1, phys});
      mesh.edges.push_back(
          {{a, m, b}, name != physical_name.end() ? name->second : std::to_string(phys)});
    }
  }
  validate_mesh(mesh, lines);
  return mesh;
}

} // namespace fsi::fem
