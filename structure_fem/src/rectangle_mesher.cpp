#include "structure_fem/rectangle_mesher.hpp"

#include <cmath>
#include <string>

#include "fsi/core/error.hpp"

namespace fsi::fem {

Mesh make_rectangle_mesh(const RectangleMeshOptions& o) {
  if (!(o.width > 0.0) || !std::isfinite(o.width))
    throw InputError("rectangle mesh: width = " + std::to_string(o.width) + ": must be > 0");
  if (!(o.height > 0.0) || !std::isfinite(o.height))
    throw InputError("rectangle mesh: height = " + std::to_string(o.height) + ": must be > 0");
  if (o.elements_x < 1 || o.elements_y < 1)
    throw InputError("rectangle mesh: elements_x = " + std::to_string(o.elements_x) +
                     ", elements_y = " + std::to_string(o.elements_y) + ": both must be >= 1");
  Mesh mesh;
  mesh.source = "rectangle mesh";
  const int nx = 2 * o.elements_x + 1, ny = 2 * o.elements_y + 1; // node rows and columns
  auto id = [nx](int i, int j) { return j * nx + i; };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      mesh.X.push_back(o.origin + Vec2(o.width * i / (nx - 1), o.height * j / (ny - 1)));
      mesh.node_label.push_back(id(i, j) + 1);
    }
  for (int q = 0; q < o.elements_y; ++q)
    for (int p = 0; p < o.elements_x; ++p) {
      const int i = 2 * p, j = 2 * q;
      if (o.diagonals == Diagonals::mirrored && 2 * p + 1 < o.elements_x) {
        // Lower-left triangle (ll, lr, ul) and upper-right triangle (lr, ur, ul), both CCW.
        mesh.elements.push_back(
            {id(i, j), id(i + 2, j), id(i, j + 2), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
        mesh.elements.push_back({id(i + 2, j), id(i + 2, j + 2), id(i, j + 2), id(i + 2, j + 1),
                                 id(i + 1, j + 2), id(i + 1, j + 1)});
        continue;
      }
      // Lower-right triangle (ll, lr, ur) and upper-left triangle (ll, ur, ul), both CCW.
      mesh.elements.push_back({id(i, j), id(i + 2, j), id(i + 2, j + 2), id(i + 1, j),
                               id(i + 2, j + 1), id(i + 1, j + 1)});
      mesh.elements.push_back({id(i, j), id(i + 2, j + 2), id(i, j + 2), id(i + 1, j + 1),
                               id(i + 1, j + 2), id(i, j + 1)});
    }
  for (std::size_t e = 0; e < mesh.elements.size(); ++e)
    mesh.element_label.push_back(static_cast<long>(e) + 1);
  for (int i = 0; i + 2 < nx; i += 2)
    mesh.edges.push_back({{id(i, 0), id(i + 1, 0), id(i + 2, 0)}, "bottom"});
  for (int j = 0; j + 2 < ny; j += 2)
    mesh.edges.push_back({{id(nx - 1, j), id(nx - 1, j + 1), id(nx - 1, j + 2)}, "right"});
  for (int i = nx - 1; i - 2 >= 0; i -= 2)
    mesh.edges.push_back({{id(i, ny - 1), id(i - 1, ny - 1), id(i - 2, ny - 1)}, "top"});
  for (int j = ny - 1; j - 2 >= 0; j -= 2)
    mesh.edges.push_back({{id(0, j), id(0, j - 1), id(0, j - 2)}, "left"});
  validate_mesh(mesh);
  return mesh;
}

} // namespace fsi::fem
