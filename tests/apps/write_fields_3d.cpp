// Writes the 3-D fields.h5 + fields.xmf that test_output_paraview_3d.py opens in ParaView: one
// frame with a 4 x 3 x 2 particle lattice (pressure, velocity) and a 2 x 1 x 1-cell T10 box mesh
// (structure_fem's box mesher, Gmsh node order) bent by a quadratic displacement, so its
// mid-edge nodes are off the straight edges. Parameters are repeated in the Python test.
#include "fsi_app/output/fields_file.hpp"
#include "structure_fem/box_mesher.hpp"

#include <filesystem>
#include <iostream>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: write_fields_3d OUTDIR\n";
    return 2;
  }
  const std::filesystem::path out = argv[1];
  std::filesystem::create_directories(out);
  fsi::app::FieldsFile file(out / "fields.h5", out / "fields.xmf");

  const auto mesh = fsi::fem::make_box_mesh({{0.0, 0.0, 0.0}, {0.2, 0.1, 0.1}, {2, 1, 1}});
  std::vector<std::int64_t> t10;
  for (const auto& e : mesh.elements) t10.insert(t10.end(), e.begin(), e.end());
  file.add_mesh_t10("solid", t10);

  file.begin_frame(0.5);
  // Particles at (0.1 i, 0.2 j, 0.3 k); velocity (x + 1, 2 y, -3 z), pressure 10 x + y + z.
  std::vector<double> xyz, velocity, pressure;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 4; ++i) {
        const double x = 0.1 * i, y = 0.2 * j, z = 0.3 * k;
        xyz.insert(xyz.end(), {x, y, z});
        velocity.insert(velocity.end(), {x + 1.0, 2.0 * y, -3.0 * z});
        pressure.push_back(10.0 * x + y + z);
      }
  file.write_grid("particles", xyz,
                  {{"pressure", 1, pressure.data()}, {"velocity", 3, velocity.data()}}, 3);
  // Displacement u(X) = (2 Y^2, 3 Z^2, 4 X^2): quadratic, so the T10 field is exact.
  std::vector<double> nodes, displacement;
  for (const auto& X : mesh.X) {
    const double u[3] = {2.0 * X.y() * X.y(), 3.0 * X.z() * X.z(), 4.0 * X.x() * X.x()};
    for (int c = 0; c < 3; ++c) {
      nodes.push_back(X[c] + u[c]);
      displacement.push_back(u[c]);
    }
  }
  file.write_grid("solid", nodes, {{"displacement", 3, displacement.data()}}, 3);
  file.end_frame();
  return 0;
}
