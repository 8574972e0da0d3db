// Gmsh .msh import: the format line, the sections in file order (gmsh_sections.cpp), the required
// physical groups (both readers); the T6 mesh with the 3-node lines turned into boundary edges of
// the triangles they bound (the T10 mesh: gmsh_reader_t10.cpp).
#include "structure_fem/gmsh_reader.hpp"

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <utility>

#include "fsi/core/error.hpp"
#include "gmsh_sections.hpp"

namespace fsi::fem {

using gmsh::Parsed;

namespace gmsh {

std::ifstream open_mesh_file(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec))
    throw InputError(path + ": not a regular file (need a Gmsh .msh file)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open the mesh file");
  return in;
}

const std::vector<long>* Parsed::physicals(const RawElement& el) const {
  if (msh22) return &el.physicals;
  const auto it = entity_physicals.find({dim - 1, el.entity});
  return it == entity_physicals.end() ? nullptr : &it->second;
}

std::string Parsed::boundary_name(long tag) const {
  const auto name = physical_name.find({dim - 1, tag});
  return name != physical_name.end() ? name->second : std::to_string(tag);
}

Parsed parse(std::istream& in, const std::string& path, int dim,
             const std::vector<std::string>& required_groups, bool surface) {
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
  p.dim = dim;
  p.surface = surface;
  p.path = path;
  p.binary = lex.binary();
  p.msh22 = msh22;
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
  if (!p.off_plane.empty()) throw InputError(p.off_plane);

  std::set<std::string> names;
  for (const auto& [key, name] : p.physical_name) names.insert(name);
  for (const auto& g : required_groups)
    if (!names.count(g))
      throw InputError(path + ": missing physical group \"" + g + "\" (the file names: " + [&] {
        std::string all;
        for (const auto& n : names) all += (all.empty() ? "" : ", ") + n;
        return all.empty() ? std::string("none") : all;
      }() + ")");
  return p;
}

} // namespace gmsh

Mesh read_gmsh(const std::string& path, const std::vector<std::string>& required_groups) {
  auto in = gmsh::open_mesh_file(path);
  return read_gmsh(in, path, required_groups);
}

Mesh read_gmsh(std::istream& in, const std::string& path,
               const std::vector<std::string>& required_groups) {
  const Parsed p = gmsh::parse(in, path, 2, required_groups);
  Mesh mesh;
  mesh.source = path;
  mesh.node_label = p.node_label;
  for (const auto& x : p.X) mesh.X.emplace_back(x.x(), x.y());
  MeshSourceLines lines;
  lines.node_line = p.node_line;
  for (const auto& el : p.elements) {
    if (el.type != p.domain_type()) continue;
    std::array<int, 6> nodes{};
    std::copy(el.nodes.begin(), el.nodes.end(), nodes.begin());
    mesh.elements.push_back(nodes);
    mesh.element_label.push_back(el.tag);
    if (!p.binary) lines.element_line.push_back(el.line);
  }

  // 3-node lines become edges (corner, mid, corner), turned so that their triangle is on the left.
  std::map<std::pair<int, int>, int> side_of; // directed corner pair of a triangle side
  for (const auto& el : mesh.elements)
    for (int s = 0; s < 3; ++s)
      side_of[{el[static_cast<std::size_t>(s)], el[static_cast<std::size_t>((s + 1) % 3)]}] = 1;
  for (const auto& raw : p.elements) {
    const std::vector<long>* physicals = p.physicals(raw);
    if (raw.type != p.boundary_type() || !physicals) continue;
    int a = raw.nodes[0], b = raw.nodes[1];
    const int m = raw.nodes[2];
    if (!side_of.count({a, b})) std::swap(a, b);
    if (!side_of.count({a, b}))
      throw InputError(p.at(raw.line) + "line element " + std::to_string(raw.tag) +
                       " is not the side of any triangle");
    for (long phys : *physicals) mesh.edges.push_back({{a, m, b}, p.boundary_name(phys)});
  }
  validate_mesh(mesh, lines);
  return mesh;
}

} // namespace fsi::fem
