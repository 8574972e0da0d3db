// STL surfaces as triangle walls: the ASCII and binary readers, and the vertex merge and the
// checks of every surface read from a file (geometry_erp/stl_reader.hpp).
#include "geometry_erp/stl_reader.hpp"

#include <Eigen/Geometry> // cross products
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <utility>

#include "fsi/core/error.hpp"

namespace fsi::erp {

namespace {

[[noreturn]] void fail(const std::string& where, const std::string& what) {
  throw InputError(where + ": " + what);
}

std::vector<std::string> words(const std::string& line) {
  std::istringstream s(line);
  return {std::istream_iterator<std::string>(s), std::istream_iterator<std::string>()};
}

double number(const std::string& word, const std::string& where) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
  if (error != std::errc() || end != word.data() + word.size())
    fail(where, "'" + word + "' is not a number");
  if (!std::isfinite(value)) fail(where, "'" + word + "' is not finite");
  return value;
}

/// The lines of an ASCII file, numbered from 1, blank ones skipped.
class Lines {
public:
  Lines(const std::string& text, const std::string& file) : in_(text), file_(file) {}
  /// The next non-blank line's words; empty at the end of the file.
  std::vector<std::string> next() {
    std::string line;
    while (std::getline(in_, line)) {
      ++number_;
      auto w = words(line);
      if (!w.empty()) return w;
    }
    return {};
  }
  std::string where() const { return file_ + ":" + std::to_string(number_); }

private:
  std::istringstream in_;
  std::string file_;
  long number_ = 0;
};

/// `expected` words (a keyword, then numbers read by the caller), or a message naming them.
void expect(const std::vector<std::string>& w, std::initializer_list<const char*> keywords,
            std::size_t count, const Lines& lines) {
  bool ok = w.size() == count;
  std::size_t i = 0;
  for (const char* k : keywords) ok = ok && w[i++] == k;
  if (ok) return;
  std::ostringstream want;
  want << "expected '";
  i = 0;
  for (const char* k : keywords) want << (i++ ? " " : "") << k;
  want << "'";
  if (count > keywords.size()) want << " and " << count - keywords.size() << " numbers";
  fail(lines.where(), want.str());
}

Vec3 vector_at(const std::vector<std::string>& w, std::size_t first, const Lines& lines) {
  return {number(w[first], lines.where()), number(w[first + 1], lines.where()),
          number(w[first + 2], lines.where())};
}

std::vector<SurfaceFacet> read_ascii(const std::string& text, const std::string& file) {
  Lines lines(text, file);
  std::vector<SurfaceFacet> facets;
  for (auto w = lines.next(); !w.empty(); w = lines.next()) {
    if (w[0] != "solid") fail(lines.where(), "expected 'solid'");
    for (w = lines.next(); !w.empty() && w[0] == "facet"; w = lines.next()) {
      SurfaceFacet f;
      expect(w, {"facet", "normal"}, 5, lines);
      f.n = vector_at(w, 2, lines);
      f.where = lines.where();
      expect(lines.next(), {"outer", "loop"}, 2, lines);
      for (Vec3& v : f.v) {
        w = lines.next();
        expect(w, {"vertex"}, 4, lines);
        v = vector_at(w, 1, lines);
      }
      expect(lines.next(), {"endloop"}, 1, lines);
      expect(lines.next(), {"endfacet"}, 1, lines);
      facets.push_back(std::move(f));
    }
    if (w.empty() || w[0] != "endsolid") fail(lines.where(), "expected 'facet' or 'endsolid'");
  }
  return facets;
}

std::uint32_t facet_count(const std::string& bytes) {
  std::uint32_t n = 0;
  std::memcpy(&n, bytes.data() + 80, sizeof n); // little-endian, as the format and x86-64
  return n;
}

std::vector<SurfaceFacet> read_binary(const std::string& bytes, const std::string& file) {
  if (bytes.size() < 84) fail(file, "binary STL shorter than its 84-byte header");
  const std::uint32_t n = facet_count(bytes);
  if (bytes.size() != 84 + 50 * static_cast<std::size_t>(n))
    fail(file, "binary STL of " + std::to_string(bytes.size()) + " bytes for " + std::to_string(n) +
                   " facets (84 + 50 n expected)");
  std::vector<SurfaceFacet> facets(n);
  for (std::size_t k = 0; k < n; ++k) {
    float c[12];
    std::memcpy(c, bytes.data() + 84 + 50 * k, sizeof c);
    SurfaceFacet& f = facets[k];
    f.where = file + ": facet " + std::to_string(k + 1);
    for (int i = 0; i < 12; ++i)
      if (!std::isfinite(c[i])) fail(f.where, "a coordinate is not finite");
    f.n = {c[0], c[1], c[2]};
    for (int j = 0; j < 3; ++j)
      f.v[static_cast<std::size_t>(j)] = {c[3 + 3 * j], c[4 + 3 * j], c[5 + 3 * j]};
  }
  return facets;
}

bool is_ascii(const std::string& bytes) {
  const bool solid = bytes.compare(0, 5, "solid") == 0 &&
                     (bytes.size() == 5 || std::isspace(static_cast<unsigned char>(bytes[5])));
  return solid && !(bytes.size() >= 84 &&
                    bytes.size() == 84 + 50 * static_cast<std::size_t>(facet_count(bytes)));
}

} // namespace

StlSurface assemble_surface(const std::vector<SurfaceFacet>& facets, const std::string& file) {
  if (facets.empty()) fail(file, "no facets");
  StlSurface s;
  std::map<std::array<double, 3>, int> index;
  std::map<std::pair<int, int>, std::pair<int, int>> edges; // (lo, hi) -> (facets on it, first)
  for (std::size_t t = 0; t < facets.size(); ++t) {
    const SurfaceFacet& f = facets[t];
    const Vec3 normal = (f.v[1] - f.v[0]).cross(f.v[2] - f.v[0]);
    double longest = 0.0;
    for (int k = 0; k < 3; ++k)
      longest = std::max(
          longest, (f.v[static_cast<std::size_t>((k + 1) % 3)] - f.v[static_cast<std::size_t>(k)])
                       .squaredNorm());
    if (!(normal.norm() > 1e-12 * longest)) fail(f.where, "degenerate facet (zero area)");
    if (f.n.dot(normal) < 0.0)
      fail(f.where, "the facet's normal points against its vertex order (flipped facet)");
    std::array<int, 3> node;
    for (int k = 0; k < 3; ++k) {
      const Vec3& p = f.v[static_cast<std::size_t>(k)];
      const auto [it, added] =
          index.try_emplace({p.x(), p.y(), p.z()}, static_cast<int>(s.points.size()));
      if (added) s.points.push_back(p);
      node[static_cast<std::size_t>(k)] = it->second;
    }
    for (int k = 0; k < 3; ++k) {
      const int a = node[static_cast<std::size_t>(k)],
                b = node[static_cast<std::size_t>((k + 1) % 3)];
      auto& [count, first] = edges[{std::min(a, b), std::max(a, b)}];
      // first: the facet that ran the edge first, + 1, negative if it ran it from hi to lo
      const int run = static_cast<int>(t + 1) * (a < b ? 1 : -1);
      if (count == 1 && (first > 0) == (run > 0))
        fail(f.where, "runs an edge the same way as " +
                          facets[static_cast<std::size_t>(std::abs(first) - 1)].where +
                          " (one of the two is flipped)");
      if (count == 2)
        fail(f.where, "an edge shared by more than two facets (non-manifold surface)");
      if (count++ == 0) first = run;
    }
    s.triangles.push_back(node);
  }
  for (const auto& [edge, use] : edges) s.open_edges += use.first == 1 ? 1 : 0;
  return s;
}

StlSurface read_stl(std::istream& in, const std::string& file) {
  const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  return assemble_surface(is_ascii(bytes) ? read_ascii(bytes, file) : read_binary(bytes, file),
                          file);
}

StlSurface read_stl_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open");
  return read_stl(in, path);
}

} // namespace fsi::erp
