// FieldSet vector fields: the component names the 2-D solvers use, a FieldList of some arrays and
// a save of the first rows, and a 3-D cloud sorted by the cells of BasicCellGrid<3> and
// BasicPeriodicGrid<3> through FieldSet::permute.
#include "particles/periodic_grid.hpp"
#include "particles/vector_field.hpp"
#include "random_cloud.hpp"

#include <catch2/catch.hpp>

using namespace fsi;
using namespace fsi::particles;

TEST_CASE("particles: vector fields keep the 2-D solvers' field names", "[particles]") {
  FieldSet f2;
  add_vector<2>(f2, "");
  add_vector<2>(f2, "v");
  add_vector<2>(f2, "", true, "0");
  add_vector<2>(f2, "n", false, "0");
  CHECK(f2.names() == std::vector<std::string>{"x", "y", "vx", "vy", "x0", "y0", "nx0", "ny0"});
  FieldSet f3;
  const auto v = add_vector<3>(f3, "v");
  f3.resize(5);
  v[2][4] = 1.5;
  CHECK(f3.names() == std::vector<std::string>{"vx", "vy", "vz"});
  CHECK(v.coords()[2][4] == 1.5);
  // Checkpoint content: the components are state reals, scratch ones are not saved.
  FieldSet::Snapshot snap;
  f3.save(snap);
  CHECK(snap.reals.size() == 3);
  CHECK(snap.reals[2][4] == 1.5);
}

TEST_CASE("particles: a FieldList names some arrays; save copies the first rows", "[particles]") {
  FieldSet f;
  const auto v = add_vector<2>(f, "v");
  auto& p = f.add_real("p");
  auto& surface = f.add_flag("surface");
  auto& id = f.add_index("id");
  f.resize(4);
  for (std::size_t i = 0; i < 4; ++i)
    v[0][i] = 1.0 + static_cast<double>(i), p[i] = 10.0 * static_cast<double>(i),
    surface[i] = static_cast<std::uint8_t>(i % 2), id[i] = static_cast<std::uint32_t>(7 + i);
  // Every array by default (8 + 8 + 8 + 1 + 4 bytes); a list: its arrays only, in names() order.
  CHECK(f.bytes_per_particle() == 29);
  FieldList some(id, p);
  some.add(v[1]);
  CHECK(f.bytes_per_particle(some) == 20);
  std::vector<std::size_t> sizes;
  f.for_each_array(some, [&](const auto& values) { sizes.push_back(sizeof(values[0])); });
  CHECK(sizes == std::vector<std::size_t>{8, 8, 4}); // vy, p, id
  // The first 3 rows (a decomposed set's owned particles), restored exactly.
  FieldSet::Snapshot snap;
  f.save(snap, 3);
  CHECK(snap.size == 3);
  CHECK(snap.reals[2] == std::vector<double>{0.0, 10.0, 20.0});
  CHECK(snap.indices[0] == std::vector<std::uint32_t>{7, 8, 9});
  p[0] = -1.0;
  f.restore(snap);
  CHECK(f.size() == 3);
  CHECK(p == std::vector<double>{0.0, 10.0, 20.0});
  CHECK(v[0] == std::vector<double>{1.0, 2.0, 3.0});
  CHECK(surface == std::vector<std::uint8_t>{0, 1, 0});
}

namespace {

/// The cell of particle i as the binning numbers it: x fastest, then y, then z.
template <class Grid> int cell_of(const Grid& g, const VectorField<3>& x, std::size_t i) {
  return (g.cell(2, x[2][i]) * g.cells(1) + g.cell(1, x[1][i])) * g.cells(0) + g.cell(0, x[0][i]);
}

/// A FieldSet holding the cloud (x, y, z), a velocity v = (2 x, y - z, i), a mass i and an index
/// i, binned by `grid` and permuted by its cell order: every array moves with its particle, and
/// each cell's particles are contiguous, in their old order. Returns the number of cells in use.
template <class Grid> int sort_and_check(Grid& grid, const test::Cloud<3>& cloud) {
  const std::size_t n = cloud.size();
  FieldSet f;
  const auto x = add_vector<3>(f, "");
  const auto v = add_vector<3>(f, "v");
  auto& mass = f.add_real("mass");
  auto& id = f.add_index("id");
  f.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    for (int a = 0; a < 3; ++a) x[a][i] = cloud.x[static_cast<std::size_t>(a)][i];
    v[0][i] = 2.0 * x[0][i], v[1][i] = x[1][i] - x[2][i], v[2][i] = static_cast<double>(i);
    mass[i] = static_cast<double>(i);
    id[i] = static_cast<std::uint32_t>(i);
  }
  grid.bin(x.coords(), n);
  std::vector<double> scratch;
  f.permute(grid.order(), scratch);
  int moved = 0, cells = 1, wrong = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = id[i];
    moved += j != i;
    for (int a = 0; a < 3; ++a) wrong += x[a][i] != cloud.x[static_cast<std::size_t>(a)][j];
    wrong += v[0][i] != 2.0 * x[0][i] || v[1][i] != x[1][i] - x[2][i];
    wrong += v[2][i] != static_cast<double>(j) || mass[i] != static_cast<double>(j);
    if (i > 0) {
      const int c0 = cell_of(grid, x, i - 1), c1 = cell_of(grid, x, i);
      wrong += c1 < c0 || (c1 == c0 && id[i] < id[i - 1]); // contiguous cells, stable
      cells += c1 != c0;
    }
  }
  CHECK(wrong == 0);
  CHECK(moved > static_cast<int>(n) / 2); // the sort did reorder
  // Binned again, the sorted cloud is in cell order already.
  grid.bin(x.coords(), n);
  for (std::size_t i = 0; i < n; ++i) wrong += grid.order()[i] != i;
  CHECK(wrong == 0);
  return cells;
}

} // namespace

TEST_CASE("particles: a FieldSet sorted by the cells of a 3-D grid", "[particles]") {
  const double side = 1.0, h = 0.15;
  SECTION("open sides (BasicCellGrid<3>; particles outside clamped into the edge cells)") {
    const auto cloud = test::random_cloud<3>(3000, side, 42);
    BasicCellGrid<3> grid(Vec3::Zero(), Vec3::Constant(side), h);
    const int cells = sort_and_check(grid, cloud);
    INFO("cells in use " << cells << " of " << grid.cells(0) * grid.cells(1) * grid.cells(2));
    CHECK(cells > 300);
  }
  SECTION("periodic in x and z (BasicPeriodicGrid<3>, particles wrapped first)") {
    auto cloud = test::random_cloud<3>(3000, side, 7);
    BasicPeriodicGrid<3> grid(Vec3::Zero(), Vec3::Constant(side), h, {true, false, true});
    for (std::size_t i = 0; i < cloud.size(); ++i)
      for (const int a : {0, 2})
        cloud.x[static_cast<std::size_t>(a)][i] =
            grid.wrap(a, cloud.x[static_cast<std::size_t>(a)][i]);
    const int cells = sort_and_check(grid, cloud);
    INFO("cells in use " << cells);
    CHECK(cells > 200);
  }
}
