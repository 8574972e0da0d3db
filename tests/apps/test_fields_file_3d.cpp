// fields.h5 / fields.xmf in 3-D: points x 3 (XYZ), 3-component vectors, T10 meshes stored in
// XDMF's Tetrahedron_10 node order, and a restart that keeps the 3-D index as it was.
#include "fsi_app/output/fields_file.hpp"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace fsi::app;
namespace fs = std::filesystem;

namespace {

std::string text_of(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

} // namespace

TEST_CASE("apps: 3-D fields: XYZ points, 3-component vectors, T10 in XDMF order",
          "[apps][output]") {
  const fs::path dir = fs::temp_directory_path() / "fsi_test_fields_3d";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path h5 = dir / "fields.h5", xmf = dir / "fields.xmf";
  // Two elements in Gmsh order, nodes 10 e + k: edge nodes 8 (3-2) and 9 (3-1) trade places.
  std::vector<std::int64_t> t10(20);
  for (std::size_t i = 0; i < t10.size(); ++i) t10[i] = static_cast<std::int64_t>(i);
  std::string after_first;
  {
    FieldsFile file(h5, xmf);
    file.add_mesh_t10("solid", t10);
    for (int k = 0; k < 2; ++k) {
      file.begin_frame(0.25 * k);
      std::vector<double> xyz(3 * 4), velocity(3 * 4), nodes(3 * 20, 0.5 * k);
      for (std::size_t i = 0; i < xyz.size(); ++i) {
        xyz[i] = 0.5 * static_cast<double>(i) + k;
        velocity[i] = -2.0 * static_cast<double>(i);
      }
      file.write_grid("particles", xyz, {{"velocity", 3, velocity.data()}}, 3);
      file.write_grid("solid", nodes, {{"displacement", 3, nodes.data()}}, 3);
      file.end_frame();
      if (k == 0) after_first = text_of(xmf);
    }
  }
  const auto p = read_dataset(h5, "frames/1/particles/position");
  CHECK(p.dims == std::vector<std::size_t>{4, 3});
  CHECK(p.values[11] == 6.5);
  const auto v = read_dataset(h5, "frames/1/particles/velocity");
  CHECK(v.dims == std::vector<std::size_t>{4, 3});
  CHECK(v.values[7] == -14.0);
  const auto conn = read_dataset(h5, "meshes/solid/t10");
  CHECK(conn.dims == std::vector<std::size_t>{2, 10});
  CHECK(conn.values ==
        std::vector<double>{0, 1, 2, 3, 4, 5, 6, 7, 9, 8, 10, 11, 12, 13, 14, 15, 16, 17, 19, 18});
  const std::string text = text_of(xmf);
  CHECK(text.find("GeometryType=\"XY\"") == std::string::npos);
  CHECK(text.find("<Topology TopologyType=\"Tetrahedron_10\" NumberOfElements=\"2\">\n    "
                  "<DataItem Dimensions=\"2 10\" NumberType=\"Int\" Precision=\"8\" "
                  "Format=\"HDF\">fields.h5:/meshes/solid/t10</DataItem>") != std::string::npos);
  CHECK(text.find("<Geometry GeometryType=\"XYZ\">\n    <DataItem Dimensions=\"20 3\"") !=
        std::string::npos);
  CHECK(text.find("<Attribute Name=\"velocity\" AttributeType=\"Vector\" Center=\"Node\">\n    "
                  "<DataItem Dimensions=\"4 3\"") != std::string::npos);
  // A restart from the first frame: the T10 mesh and the XYZ grids are read back as written.
  { FieldsFile restarted(h5, xmf, 1); }
  CHECK(text_of(xmf) == after_first);
  CHECK(read_dataset(h5, "meshes/solid/t10").values == conn.values);
}
