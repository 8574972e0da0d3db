// STL surfaces as triangle walls (issue 43): a unit cube written as ASCII and as binary STL reads
// back to the same 8 nodes and 12 triangles with its orientation (enclosed volume +1 by the
// divergence theorem), an open box counts its 4 open edges, and every malformed or inconsistent
// file is refused with its whole message.
#include <catch2/catch.hpp>

#include <cstdint>
#include <cstring>
#include <sstream>

#include "fsi/core/error.hpp"
#include "geometry_erp/stl_reader.hpp"
#include "geometry_erp/triangle_wall_set.hpp"

using namespace fsi;
using namespace fsi::erp;

namespace {

/// The unit cube's corners (index x + 2y + 4z) and its 12 facets, counter-clockwise from outside.
const std::array<Vec3, 8> corner = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0),
                                    Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(0, 1, 1), Vec3(1, 1, 1)};
const std::vector<std::array<int, 3>> cube = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6},
                                              {0, 1, 5}, {0, 5, 4}, {2, 6, 7}, {2, 7, 3},
                                              {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};

Vec3 unit_normal(const std::array<int, 3>& t) {
  const Vec3 &a = corner[t[0]], &b = corner[t[1]], &c = corner[t[2]];
  return (b - a).cross(c - a).normalized();
}

std::string ascii(const std::vector<std::array<int, 3>>& facets) {
  std::ostringstream s;
  s << "solid cube\n";
  for (const auto& t : facets) {
    const Vec3 n = unit_normal(t);
    s << "  facet normal " << n.x() << ' ' << n.y() << ' ' << n.z() << "\n    outer loop\n";
    for (const int i : t)
      s << "      vertex " << corner[i].x() << ' ' << corner[i].y() << ' ' << corner[i].z() << '\n';
    s << "    endloop\n  endfacet\n";
  }
  s << "endsolid cube\n";
  return s.str();
}

std::string binary(const std::vector<std::array<int, 3>>& facets, const std::string& header) {
  std::string out(80, ' ');
  out.replace(0, header.size(), header);
  const auto n = static_cast<std::uint32_t>(facets.size());
  out.append(reinterpret_cast<const char*>(&n), sizeof n);
  for (const auto& t : facets) {
    float c[12];
    const Vec3 nv = unit_normal(t);
    for (int k = 0; k < 3; ++k) c[k] = static_cast<float>(nv[k]);
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) c[3 + 3 * j + k] = static_cast<float>(corner[t[j]][k]);
    out.append(reinterpret_cast<const char*>(c), sizeof c);
    out.append(2, '\0');
  }
  return out;
}

StlSurface read(const std::string& text) {
  std::istringstream in(text);
  return read_stl(in, "f.stl");
}

std::string message(const std::string& text) {
  try {
    read(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

/// (1/6) sum a . (b x c): the enclosed volume, positive for outward facets.
double volume(const StlSurface& s) {
  double v = 0.0;
  for (const auto& t : s.triangles) v += s.points[t[0]].dot(s.points[t[1]].cross(s.points[t[2]]));
  return v / 6.0;
}

} // namespace

TEST_CASE("STL: a cube in ASCII and binary reads to 8 shared nodes, 12 facets, volume +1",
          "[geometry_erp][stl]") {
  const StlSurface a = read(ascii(cube));
  CHECK(a.points.size() == 8);
  CHECK(a.triangles.size() == 12);
  CHECK(a.open_edges == 0);
  CHECK_THAT(volume(a), Catch::Matchers::WithinAbs(1.0, 1e-15));
  for (const std::string header : {"binary cube", "solid cube (a binary file)"}) {
    const StlSurface b = read(binary(cube, header));
    CHECK(b.points == a.points);
    CHECK(b.triangles == a.triangles);
    CHECK(b.open_edges == 0);
  }
  // As walls: every face normal is the STL facet's, out of the cube (an obstacle).
  TriangleWallSet walls;
  walls.add_triangles(a.points, a.triangles, 0);
  for (int t = 0; t < 12; ++t)
    CHECK((walls.face_normal(t) - unit_normal(cube[static_cast<std::size_t>(t)])).norm() < 1e-15);
}

TEST_CASE("STL: an open box (a tank without its lid) counts its 4 open edges",
          "[geometry_erp][stl]") {
  std::vector<std::array<int, 3>> box = cube;
  box.erase(box.begin() + 2, box.begin() + 4); // the two facets of z = 1
  const StlSurface s = read(ascii(box));
  CHECK(s.triangles.size() == 10);
  CHECK(s.open_edges == 4);
}

TEST_CASE("STL: malformed and inconsistent files are refused naming file, line or facet",
          "[geometry_erp][stl]") {
  std::string text = ascii(cube);
  SECTION("a flipped facet with its normal") {
    auto facets = cube;
    std::swap(facets[3][1], facets[3][2]);
    std::string t = ascii(facets);
    // its stored normal is the flipped one; give it the original, outward normal
    const Vec3 n = unit_normal(cube[3]);
    std::ostringstream want;
    want << "facet normal " << n.x() << ' ' << n.y() << ' ' << n.z();
    const std::size_t at =
        t.find("facet normal", t.find("endfacet", t.find("endfacet", t.find("endfacet") + 1) + 1));
    t.replace(at, t.find('\n', at) - at, want.str());
    CHECK(message(t) ==
          "f.stl:23: the facet's normal points against its vertex order (flipped facet)");
  }
  SECTION("a flipped facet with a zero normal: its edge runs the same way as its neighbour's") {
    auto facets = cube;
    std::swap(facets[3][1], facets[3][2]);
    std::string t = ascii(facets);
    const std::size_t at =
        t.find("facet normal", t.find("endfacet", t.find("endfacet", t.find("endfacet") + 1) + 1));
    t.replace(at, t.find('\n', at) - at, "facet normal 0 0 0");
    CHECK(message(t) ==
          "f.stl:23: runs an edge the same way as f.stl:16 (one of the two is flipped)");
  }
  SECTION("a degenerate facet") {
    auto facets = cube;
    facets.push_back({0, 1, 1});
    CHECK(message(ascii(facets)).find(":86: degenerate facet (zero area)") != std::string::npos);
  }
  SECTION("three facets on one edge") {
    auto facets = cube;
    facets.push_back({0, 3, 6}); // the diagonal 0-3 of z = 0 a third time
    CHECK(message(ascii(facets)) ==
          "f.stl:86: an edge shared by more than two facets (non-manifold surface)");
  }
  SECTION("syntax") {
    const std::size_t at = text.find("outer loop");
    CHECK(message(text.replace(at, 10, "outer lop")) == "f.stl:3: expected 'outer loop'");
  }
  SECTION("a word that is not a number") {
    const std::size_t at = text.find("vertex 0 0 0");
    CHECK(message(text.replace(at, 12, "vertex 0 x 0")) == "f.stl:4: 'x' is not a number");
  }
  SECTION("no endsolid") {
    CHECK(message(text.substr(0, text.find("endsolid"))) ==
          "f.stl:85: expected 'facet' or 'endsolid'");
  }
  SECTION("a binary file of the wrong size") {
    CHECK(message(binary(cube, "cube") + "x") ==
          "f.stl: binary STL of 685 bytes for 12 facets (84 + 50 n expected)");
  }
  SECTION("a binary facet that is not finite") {
    std::string b = binary(cube, "cube");
    const float nan = std::numeric_limits<float>::quiet_NaN();
    std::memcpy(b.data() + 84 + 50 * 4 + 12, &nan, sizeof nan);
    CHECK(message(b) == "f.stl: facet 5: a coordinate is not finite");
  }
  SECTION("a file that does not exist") {
    CHECK_THROWS_WITH(read_stl_file("/nonexistent/tank.stl"), "/nonexistent/tank.stl: cannot open");
  }
}

TEST_CASE(
    "STL: the seed files (a cube written by Python, ASCII and binary) read as the test's cube",
    "[geometry_erp][stl]") {
  const StlSurface want = read(ascii(cube));
  for (const char* name : {"cube_ascii.stl", "cube_binary.stl"}) {
    const StlSurface s = read_stl_file(std::string(FSI_TEST_DATA) + "/stl/" + name);
    CHECK(s.points == want.points);
    CHECK(s.triangles == want.triangles);
  }
}
