#include "structure_fem/gmsh_reader.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <utility>

#include "fsi/core/error.hpp"

namespace fsi::fem {

namespace {

/// Largest integer accepted anywhere (tags, counts): far beyond any real mesh, small enough that
/// no count or sign flip overflows.
constexpr long kLargest = 1L << 40;

/// A token or a stretch of a file as a message may show it: at most 40 characters, control and
/// non-ASCII bytes escaped as \xNN (a binary file never floods the terminal).
std::string shown(const std::string& t) {
  std::string out;
  for (std::size_t i = 0; i < t.size() && i < 40; ++i) {
    const auto c = static_cast<unsigned char>(t[i]);
    if (c >= 0x20 && c < 0x7f && c != '\\') {
      out += static_cast<char>(c);
    } else {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", c);
      out += buf;
    }
  }
  if (t.size() > 40) out += "...";
  return out;
}

/// A .msh file held whole: whitespace-separated tokens with the line each came from (ASCII), and
/// little-endian values at a byte offset (binary sections of `-bin` files). Messages name the
/// line (`FILE:LINE: what`) in ASCII files and the byte offset in binary ones (`FILE: byte N:`).
class Lexer {
public:
  Lexer(std::string data, std::string path) : path_(std::move(path)), data_(std::move(data)) {
    for (char c : data_) lines_ += c == '\n';
    if (!data_.empty() && data_.back() != '\n') ++lines_;
  }
  bool blank() const {
    return std::all_of(data_.begin(), data_.end(),
                       [](char c) { return std::isspace(static_cast<unsigned char>(c)); });
  }
  int line() const { return static_cast<int>(std::min(line_, std::max<long>(lines_, 1))); }
  const std::string& path() const { return path_; }
  void set_binary() { binary_ = true; }
  bool binary() const { return binary_; }
  /// "FILE:LINE: " (ASCII) or "FILE: byte N: " (binary).
  std::string where() const {
    return binary_ ? path_ + ": byte " + std::to_string(pos_) + ": "
                   : path_ + ":" + std::to_string(line()) + ": ";
  }
  [[noreturn]] void fail(const std::string& what) const { throw InputError(where() + what); }
  [[noreturn]] void end_of_file(const std::string& what) const {
    throw InputError((binary_ ? path_ + ": " : path_ + ":" + std::to_string(line()) + ": ") +
                     "unexpected end of file while reading " + what + " (truncated file?)");
  }
  std::string token(const std::string& what) {
    while (pos_ < data_.size() && std::isspace(static_cast<unsigned char>(data_[pos_])))
      line_ += data_[pos_++] == '\n';
    if (pos_ >= data_.size()) end_of_file(what);
    const std::size_t start = pos_;
    while (pos_ < data_.size() && !std::isspace(static_cast<unsigned char>(data_[pos_]))) ++pos_;
    return data_.substr(start, pos_ - start);
  }
  bool at_end() {
    while (pos_ < data_.size() && std::isspace(static_cast<unsigned char>(data_[pos_])))
      line_ += data_[pos_++] == '\n';
    return pos_ >= data_.size();
  }
  long integer(const std::string& what) {
    const std::string t = token(what);
    long v = 0;
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (ec != std::errc() || end != t.data() + t.size())
      fail("expected an integer for " + what + ", found \"" + shown(t) + "\"");
    return in_range(v, what);
  }
  double real(const std::string& what) {
    const std::string t = token(what);
    try {
      std::size_t used = 0;
      const double v = std::stod(t, &used);
      if (used == t.size() && std::isfinite(v)) return v;
    } catch (const std::exception&) {
    }
    fail("expected a finite number for " + what + ", found \"" + shown(t) + "\"");
  }
  /// The unread rest of the current line (used for quoted names).
  std::string rest_of_line() {
    const std::size_t end = std::min(data_.find('\n', pos_), data_.size());
    std::string r = data_.substr(pos_, end - pos_);
    pos_ = end;
    return r;
  }
  void expect(const std::string& keyword) {
    const std::string t = token(keyword);
    if (t != keyword) fail("expected " + keyword + ", found \"" + shown(t) + "\"");
  }
  /// The newline that ends an ASCII header line before binary data.
  void skip_newline() {
    if (pos_ < data_.size() && data_[pos_] == '\r') ++pos_;
    if (pos_ < data_.size() && data_[pos_] == '\n') ++pos_, ++line_;
  }
  /// The start of a msh 4.1 section's data: in a binary file, after the section's line.
  void begin_section() {
    if (binary_) skip_newline();
  }
  /// The `keyword` line that ends a msh 4.1 section (in a binary file, after the data's newline).
  void end_section(const std::string& keyword) {
    if (binary_) skip_newline();
    expect(keyword);
  }

  // Binary values (the file's data size is 8: size_t is 8 bytes, int 4, double 8).
  template <class T> T raw(const std::string& what) {
    if (data_.size() - pos_ < sizeof(T)) end_of_file(what);
    T v;
    std::memcpy(&v, data_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    return v;
  }
  long bin_int(const std::string& what) { return in_range(raw<std::int32_t>(what), what); }
  long bin_size(const std::string& what) {
    const std::size_t at = pos_;
    const auto v = raw<std::uint64_t>(what);
    if (v > static_cast<std::uint64_t>(kLargest)) {
      pos_ = at;
      fail(what + " " + std::to_string(v) + " is out of range");
    }
    return static_cast<long>(v);
  }
  double bin_real(const std::string& what) {
    const std::size_t at = pos_;
    const double v = raw<double>(what);
    if (!std::isfinite(v)) {
      pos_ = at;
      fail("expected a finite number for " + what + ", found " + std::to_string(v));
    }
    return v;
  }

  // The same read in the file's encoding: a count or tag stored as size_t in binary files, an
  // int tag, a double; text in ASCII files.
  long size(const std::string& what) { return binary_ ? bin_size(what) : integer(what); }
  long tag(const std::string& what) { return binary_ ? bin_int(what) : integer(what); }
  double number(const std::string& what) { return binary_ ? bin_real(what) : real(what); }

private:
  long in_range(long v, const std::string& what) const {
    if (v < -kLargest || v > kLargest) fail(what + " " + std::to_string(v) + " is out of range");
    return v;
  }

  std::string path_;
  std::string data_;
  std::size_t pos_ = 0;
  long line_ = 1, lines_ = 0;
  bool binary_ = false;
};

int nodes_per_element(Lexer& lex, long type, long tag) {
  const std::string element = "element " + std::to_string(tag) + ": ";
  switch (type) {
  case 9:
    return 6; // 6-node triangle
  case 8:
    return 3; // 3-node line
  case 15:
    return 1; // point
  case 2:
    lex.fail(element + "3-node triangle (type 2): wrong element order, need second-order 6-node "
                       "triangles (type 9): mesh with gmsh -2 -order 2");
  case 1:
    lex.fail(element + "2-node line (type 1): wrong element order, need 3-node lines (type 8): "
                       "mesh with gmsh -2 -order 2");
  case 3:
  case 10:
  case 16:
    lex.fail(element + "quadrangle (type " + std::to_string(type) +
             "): need 6-node triangles (type 9): remove Recombine (Mesh.RecombineAll = 0) and "
             "mesh with gmsh -2 -order 2");
  case 21:
  case 23:
  case 25:
    lex.fail(element + "triangle of order 3 or more (type " + std::to_string(type) +
             "): need 6-node triangles (type 9): mesh with gmsh -2 -order 2");
  default:
    lex.fail(element + "unsupported element type " + std::to_string(type) +
             " (only 9, 8 and 15: a 2D mesh from gmsh -2 -order 2)");
  }
}

/// A node's z: the mesh must lie in the plane z = 0.
void check_planar(Lexer& lex, long tag, double z) {
  if (std::abs(z) > 1e-12)
    lex.fail("node " + std::to_string(tag) + ": z = " + std::to_string(z) +
             " m: the mesh must lie in the plane z = 0 (draw the geometry at z = 0)");
}

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

void add_node(Lexer& lex, Parsed& p, long tag, double x, double y, double z, int at) {
  check_planar(lex, tag, z);
  const auto [it, fresh] = p.node_index.emplace(tag, static_cast<int>(p.mesh.X.size()));
  if (!fresh)
    throw InputError(lex.binary()
                         ? lex.where() + "node " + std::to_string(tag) + ": node tag given twice"
                         : lex.path() + ":" + std::to_string(at) + ": node " + std::to_string(tag) +
                               ": node tag given twice");
  p.mesh.X.emplace_back(x, y);
  p.mesh.node_label.push_back(tag);
  if (!lex.binary()) p.lines.node_line.push_back(at);
}

/// One element of type `type` with its nodes (gmsh tags) read by `node`.
template <class Next>
void add_element(Lexer& lex, Parsed& p, long type, long tag, long entity, int at, Next node,
                 std::vector<long> physicals = {}, bool msh22 = false) {
  const int nn = nodes_per_element(lex, type, tag);
  std::array<long, 6> tags{};
  for (int k = 0; k < nn; ++k) {
    tags[static_cast<std::size_t>(k)] = node();
    if (!p.node_index.count(tags[static_cast<std::size_t>(k)]))
      lex.fail("element " + std::to_string(tag) + ": unknown node " +
               std::to_string(tags[static_cast<std::size_t>(k)]));
  }
  if (type == 9) {
    std::array<long, 3> corners{tags[0], tags[1], tags[2]};
    std::sort(corners.begin(), corners.end());
    if (msh22 && !p.triangles.insert(corners).second) return; // the same triangle, another group
    std::array<int, 6> el{};
    for (std::size_t k = 0; k < 6; ++k) el[k] = p.node_index.at(tags[k]);
    p.mesh.elements.push_back(el);
    p.mesh.element_label.push_back(tag);
    if (!lex.binary()) p.lines.element_line.push_back(at);
  } else if (type == 8) {
    p.raw_lines.push_back({{tags[0], tags[1], tags[2]}, tag, entity, at, std::move(physicals)});
  }
}

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

// A format 2.2 section: its record count, then each record's tag and the line it is on.
template <class Record>
void read_records_22(Lexer& lex, const char* count, const char* tag_name, Record record) {
  const long n = lex.integer(count);
  for (long i = 0; i < n; ++i) {
    const long tag = lex.integer(tag_name);
    record(tag, lex.line());
  }
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
        [&] { return lex.integer("an element node"); }, physicals, true);
  });
  lex.expect("$EndElements");
}

} // namespace

Mesh read_gmsh(const std::string& path, const std::vector<std::string>& required_groups) {
  std::error_code ec;
  if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec))
    throw InputError(path + ": not a regular file (need a Gmsh .msh file)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open the mesh file");
  return read_gmsh(in, path, required_groups);
}

Mesh read_gmsh(std::istream& in, const std::string& path,
               const std::vector<std::string>& required_groups) {
  std::string data{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  Lexer lex(std::move(data), path);
  if (lex.blank()) throw InputError(path + ": empty file (need a Gmsh .msh file)");
  lex.expect("$MeshFormat");
  const std::string version = lex.token("the format version");
  if (version != "4.1" && version != "2.2")
    lex.fail("unsupported .msh version " + shown(version) +
             ", need 4.1 or 2.2 (write it with gmsh -format msh41)");
  const bool msh22 = version == "2.2";
  const long file_type = lex.integer("the file type");
  const long data_size = lex.integer("the data size");
  if (file_type == 1) {
    if (msh22)
      lex.fail("binary .msh 2.2 is not supported: write ASCII 2.2 (-format msh22 without -bin) "
               "or 4.1 (gmsh -format msh41 -bin)");
    if (data_size != 8)
      lex.fail("binary .msh with data size " + std::to_string(data_size) + ", need 8");
    lex.skip_newline();
    lex.set_binary();
    if (lex.raw<std::int32_t>("the endianness check") != 1)
      lex.fail("binary .msh of another byte order (big-endian): write it on this machine or "
               "as ASCII (gmsh -format msh41)");
  } else if (file_type != 0) {
    lex.fail("file type " + std::to_string(file_type) + ", need 0 (ASCII) or 1 (binary)");
  }
  lex.expect("$EndMeshFormat");

  Parsed p;
  p.mesh.source = path;
  bool have_nodes = false, have_elements = false;
  while (!lex.at_end()) {
    const std::string section = lex.token("a section");
    if (section == "$PhysicalNames") {
      read_physical_names(lex, p);
    } else if (section == "$Entities" && !msh22) {
      read_entities_41(lex, p);
    } else if (section == "$Nodes") {
      if (have_nodes) lex.fail("a second $Nodes section");
      have_nodes = true;
      msh22 ? read_nodes_22(lex, p) : read_nodes_41(lex, p);
    } else if (section == "$Elements") {
      if (have_elements) lex.fail("a second $Elements section");
      have_elements = true;
      msh22 ? read_elements_22(lex, p) : read_elements_41(lex, p);
    } else if (section.size() > 1 && section[0] == '$' && !lex.binary()) {
      const std::string end = "$End" + section.substr(1);
      while (lex.token(end) != end) {
      }
    } else if (section.size() > 1 && section[0] == '$') {
      // An unknown binary section cannot be skipped token by token: find its end marker.
      lex.fail("section " + shown(section) +
               " is not read in binary files (mesh only nodes, elements, physical names)");
    } else {
      lex.fail("expected a section ($Name), found \"" + shown(section) + "\"");
    }
  }
  if (!have_nodes) throw InputError(path + ": no $Nodes section");
  if (!have_elements) throw InputError(path + ": no $Elements section");
  Mesh& mesh = p.mesh;

  std::set<std::string> names;
  for (const auto& [key, name] : p.physical_name) names.insert(name);
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
  for (const auto& raw : p.raw_lines) {
    const std::vector<long>* physicals = &raw.physicals;
    if (!msh22) {
      const auto it = p.entity_physicals.find({1, raw.entity});
      if (it == p.entity_physicals.end()) continue;
      physicals = &it->second;
    }
    int a = p.node_index.at(raw.nodes[0]), b = p.node_index.at(raw.nodes[1]);
    const int m = p.node_index.at(raw.nodes[2]);
    if (!side_of.count({a, b})) std::swap(a, b);
    if (!side_of.count({a, b}))
      throw InputError((lex.binary() ? path + ": " : path + ":" + std::to_string(raw.line) + ": ") +
                       "line element " + std::to_string(raw.tag) +
                       " is not the side of any triangle");
    for (long phys : *physicals) {
      const auto name = p.physical_name.find({1, phys});
      mesh.edges.push_back(
          {{a, m, b}, name != p.physical_name.end() ? name->second : std::to_string(phys)});
    }
  }
  validate_mesh(mesh, p.lines);
  return mesh;
}

} // namespace fsi::fem
