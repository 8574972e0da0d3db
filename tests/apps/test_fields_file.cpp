// fields.h5 / fields.xmf: frames written are read back equal, and the XDMF names only datasets
// that exist.
#include "fsi_app/output/fields_file.hpp"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

using namespace fsi::app;
namespace fs = std::filesystem;

TEST_CASE("apps: HDF5 frames round-trip and the XDMF references exist", "[apps][output]") {
  const fs::path dir = fs::temp_directory_path() / "fsi_test_fields";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::vector<std::int64_t> t6 = {0, 1, 2, 3, 4, 5};
  std::vector<std::vector<double>> positions;
  {
    FieldsFile file(dir / "fields.h5", dir / "fields.xmf");
    file.add_mesh("beam", t6);
    for (int k = 0; k < 3; ++k) {
      file.begin_frame(0.1 * k);
      std::vector<double> particles(2 * 5), pressure(5);
      for (int i = 0; i < 10; ++i) particles[i] = 0.25 * i + k;
      for (int i = 0; i < 5; ++i) pressure[i] = 1000.0 * i - k;
      file.write_grid("particles", particles, {{"pressure", 1, pressure.data()}});
      std::vector<double> nodes(12, 0.5 * k), displacement(12, -0.125 * k);
      file.write_grid("beam", nodes, {{"displacement", 2, displacement.data()}});
      file.end_frame();
      positions.push_back(particles);
    }
    CHECK(file.frames() == 3);
  }
  const fs::path h5 = dir / "fields.h5";
  for (int k = 0; k < 3; ++k) {
    CHECK(read_frame_time(h5, k) == Approx(0.1 * k).margin(1e-15));
    const auto p = read_dataset(h5, "frames/" + std::to_string(k) + "/particles/position");
    CHECK(p.dims == std::vector<std::size_t>{5, 2});
    CHECK(p.values == positions[static_cast<std::size_t>(k)]);
    const auto pr = read_dataset(h5, "frames/" + std::to_string(k) + "/particles/pressure");
    CHECK(pr.values[4] == 4000.0 - k);
    const auto d = read_dataset(h5, "frames/" + std::to_string(k) + "/beam/displacement");
    CHECK(d.dims == std::vector<std::size_t>{6, 2});
    CHECK(d.values[11] == -0.125 * k);
  }
  const auto conn = read_dataset(h5, "meshes/beam/t6");
  CHECK(conn.values == std::vector<double>{0, 1, 2, 3, 4, 5});

  std::ifstream in(dir / "fields.xmf");
  std::stringstream xmf;
  xmf << in.rdbuf();
  const std::string text = xmf.str();
  const std::regex item("fields\\.h5:(/[^<]+)<");
  int references = 0;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), item); it != std::sregex_iterator();
       ++it) {
    INFO((*it)[1].str());
    CHECK_NOTHROW(read_dataset(h5, (*it)[1].str()));
    ++references;
  }
  CHECK(references == 3 * 5 + 3); // per frame: 2 positions + 2 fields + vertices; t6 once
  CHECK(text.find("Triangle_6") != std::string::npos);
  CHECK(text.find("<Time Value=\"0.2\"/>") != std::string::npos);
}
