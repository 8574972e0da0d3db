// fluid.type: emps in a 3-D scene (issue 43): the shipped hydrostatic_tank_emps_3d builds its
// closed box tank of 12 triangles (or reads it from an STL file, to the same run), answers its
// probes, continues bitwise from a checkpoint, and what 3-D does not have yet is refused by name.
#include "emps/emps_model3.hpp"
#include "fsi/core/error.hpp"
#include "fsi/core/state_archive.hpp"
#include "fsi_app/scene.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <tuple>
#include <utility>

using namespace fsi;
using namespace fsi::app;

namespace {

const std::string kScene = FSI_SOURCE_DIR "/data/scenes/hydrostatic_tank_emps_3d.yaml";
const std::string kStlScene = FSI_SOURCE_DIR "/data/scenes/hydrostatic_tank_emps_3d_stl.yaml";
constexpr double kDt = 5e-4; // the scene's step

double probe(const emps_plugin::EmpsModel3& model, const std::string& quantity) {
  ProbeSpec p;
  p.quantity = quantity;
  p.point3 = Vec3(0.1, 0.01, 0.1);
  p.box3_min = Vec3::Zero(), p.box3_max = Vec3(0.2, 0.02, 0.2);
  return *model.probe(p);
}

void advance(emps_plugin::EmpsModel3& model, int from, int steps) {
  for (int s = from; s < from + steps; ++s) model.advance(s * kDt, kDt);
}

} // namespace

TEST_CASE("apps: the 3-D EMPS scene's tank is 12 triangles facing the water, its probes read in "
          "3-D",
          "[apps][emps][3d]") {
  const Scene scene = load_scene(kScene, {});
  REQUIRE(scene.dimension == 3);
  emps_plugin::EmpsModel3 model(scene);
  const auto& f = model.fluid();
  CHECK(f.particles().size() == 1000);
  REQUIRE(model.walls().triangles().size() == 12);
  int floor = 0;
  for (int t = 0; t < 12; ++t)
    floor += model.walls().face_normal(t) == Vec3(0.0, 1.0, 0.0); // into the water, up
  CHECK(floor == 2);
  // At rest on the lattice: the nearest centres sit l0/2 from the walls, the interior of the
  // bottom layer has pnd = n0 (the floor's virtual lattice, eq. 20).
  CHECK(probe(model, "wall_gap") == Approx(0.01).epsilon(1e-12));
  CHECK(probe(model, "particles") == 1000.0);
  const auto& p = f.particles();
  for (std::size_t i = 0; i < p.size(); ++i)
    if (std::abs(p.position[1][i] - 0.01) < 1e-9 && std::abs(p.position[0][i] - 0.09) < 1e-9 &&
        std::abs(p.position[2][i] - 0.09) < 1e-9)
      CHECK(std::abs(p.pnd[i] / f.n0() - 1.0) < 1e-12);
  advance(model, 0, 4);
  CHECK(probe(model, "kinetic_energy") > 0.0);
  CHECK(probe(model, "mean_speed") > 0.0);
  CHECK(probe(model, "mean_pressure") > 0.0);
  CHECK(probe(model, "pressure") > 0.0);
  CHECK(probe(model, "wall_gap") > 0.0);
  CHECK(probe(model, "particles") == 1000.0);
}

TEST_CASE("apps: the 3-D EMPS water_height gauge reads the depth of still water",
          "[apps][emps][3d]") {
  // The shipped tank at rest: 10 layers of l0 = 0.02 m, the top centres at 0.19 m, so the still
  // layer's top is H = 0.2 m wherever the gauge stands, and H - y0 above a point at y0.
  const Scene scene = load_scene(kScene, {});
  emps_plugin::EmpsModel3 model(scene);
  const auto gauge = [&](const Vec3& at) {
    ProbeSpec p;
    p.quantity = "water_height";
    p.point3 = at;
    return *model.probe(p);
  };
  CHECK(gauge(Vec3(0.1, 0.0, 0.1)) == Approx(0.2).epsilon(1e-12));
  CHECK(gauge(Vec3(0.0, 0.0, 0.0)) == Approx(0.2).epsilon(1e-12)); // the tank's corner
  CHECK(gauge(Vec3(0.13, 0.05, 0.07)) == Approx(0.15).epsilon(1e-12));
  CHECK(gauge(Vec3(0.1, 0.25, 0.1)) == 0.0); // above the water
  CHECK(gauge(Vec3(0.25, 0.0, 0.1)) == 0.0); // l0 beyond the tank's side: no particle near
}

TEST_CASE("apps: the 3-D EMPS tank read from its STL file runs as the box of keys",
          "[apps][emps][3d]") {
  emps_plugin::EmpsModel3 box(load_scene(kScene, {}));
  emps_plugin::EmpsModel3 stl(load_scene(kStlScene, {}));
  CHECK(stl.walls().triangles().size() == 12);
  advance(box, 0, 4);
  advance(stl, 0, 4);
  const auto &a = box.fluid().particles(), &b = stl.fluid().particles();
  REQUIRE(a.size() == b.size());
  double worst = 0.0; // the triangles differ in order and diagonals: round-off, not bitwise
  for (std::size_t i = 0; i < a.size(); ++i)
    for (int c = 0; c < 3; ++c)
      worst = std::max(worst, std::abs(a.position[c][i] - b.position[c][i]));
  INFO("largest position difference " << worst << " m");
  CHECK(worst < 1e-12);
}

namespace {

const std::string kMsh = FSI_SOURCE_DIR "/data/meshes/hydrostatic_tank_emps_3d.msh";

/// The shipped .msh tank edited in its $Elements blocks: `face`'s block emptied (a hole), or the
/// first triangle of `flip`'s block with two corners swapped (0: none).
std::string edited_msh(const std::string& name, int face, int flip) {
  const std::string path = (std::filesystem::temp_directory_path() / name).string();
  std::ifstream in(kMsh);
  std::ofstream out(path);
  std::string line;
  while (std::getline(in, line) && line != "$Elements") out << line << '\n';
  out << line << '\n';
  std::getline(in, line);
  out << line << '\n'; // blocks, elements, smallest and largest tag (the reader reads the blocks)
  int blocks = std::stoi(line);
  for (int b = 0; b < blocks; ++b) {
    std::getline(in, line);
    std::istringstream h(line);
    int dim, entity, type, n;
    h >> dim >> entity >> type >> n;
    out << dim << ' ' << entity << ' ' << type << ' ' << (entity == face ? 0 : n) << '\n';
    for (int e = 0; e < n; ++e) {
      std::getline(in, line);
      if (entity == face) continue;
      if (entity == flip && e == 0) {
        std::istringstream t(line);
        long tag, a, b2, c;
        t >> tag >> a >> b2 >> c;
        line = std::to_string(tag) + ' ' + std::to_string(a) + ' ' + std::to_string(c) + ' ' +
               std::to_string(b2);
      }
      out << line << '\n';
    }
  }
  while (std::getline(in, line)) out << line << '\n';
  return path;
}

} // namespace

TEST_CASE("apps: the 3-D EMPS tank read from a Gmsh surface mesh runs as the box of keys",
          "[apps][emps][3d]") {
  emps_plugin::EmpsModel3 box(load_scene(kScene, {}));
  emps_plugin::EmpsModel3 msh(load_scene(kStlScene, {"fluid.tank_file=" + kMsh}));
  CHECK(msh.walls().triangles().size() == 116); // gmsh -2 at h = 0.1 m: triangulated otherwise
  advance(box, 0, 4);
  advance(msh, 0, 4);
  const auto &a = box.fluid().particles(), &b = msh.fluid().particles();
  REQUIRE(a.size() == b.size());
  double worst = 0.0, worst_p = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (int c = 0; c < 3; ++c)
      worst = std::max(worst, std::abs(a.position[c][i] - b.position[c][i]));
    worst_p = std::max(worst_p, std::abs(a.p[i] - b.p[i]));
  }
  INFO("largest position difference " << worst << " m, pressure " << worst_p << " Pa");
  CHECK(worst < 1e-12);
  CHECK(worst_p < 1e-6); // of rho g H = 1962 Pa
}

TEST_CASE("apps: a Gmsh tank with a hole below the water or a flipped triangle is refused",
          "[apps][emps][3d]") {
  const std::string open = edited_msh("test_emps_plugin_3d_open.msh", 5, 0); // no face x = 0
  const std::string flipped = edited_msh("test_emps_plugin_3d_flipped.msh", 0, 3);
  CHECK_THROWS_WITH(emps_plugin::EmpsModel3(load_scene(kStlScene, {"fluid.tank_file=" + open})),
                    Catch::Contains("fluid.tank_file: " + open + ": facet ") &&
                        Catch::Contains("has an open edge at (0, ") &&
                        Catch::Contains("below the water's top"));
  CHECK_THROWS_WITH(emps_plugin::EmpsModel3(load_scene(kStlScene, {"fluid.tank_file=" + flipped})),
                    Catch::Contains(flipped + ":") && Catch::Contains(": element ") &&
                        Catch::Contains("(one of the two is flipped)"));
  std::filesystem::remove(open);
  std::filesystem::remove(flipped);
}

TEST_CASE("apps: a 3-D EMPS run continued from its checkpoint is bitwise the run that was not "
          "interrupted",
          "[apps][emps][3d]") {
  const Scene scene = load_scene(kScene, {});
  emps_plugin::EmpsModel3 whole(scene), first(scene), second(scene);
  advance(whole, 0, 6);
  advance(first, 0, 3);
  StateArchive archive;
  first.write_state(archive);
  // Static walls are their own walls at t^n: no copy of them in the fluid's state.
  std::size_t walls_before = 0;
  for (const auto& entry : archive.all_reals())
    walls_before += entry.first.find("walls_before/") != std::string::npos;
  CHECK(walls_before == 0);
  second.read_state(archive);
  advance(second, 3, 3);
  const auto &a = whole.fluid().particles(), &b = second.fluid().particles();
  REQUIRE(a.size() == b.size());
  std::size_t differ = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (int c = 0; c < 3; ++c)
      differ += a.position[c][i] != b.position[c][i] || a.velocity[c][i] != b.velocity[c][i];
    differ += a.p[i] != b.p[i] || a.pnd[i] != b.pnd[i];
  }
  CHECK(differ == 0);
}

TEST_CASE("apps: a 3-D EMPS tank moved by fluid.tank_motion: its triangles follow the motion, a "
          "wall moving into the water raises the pressure beside it, one moving away lowers it",
          "[apps][emps][3d]") {
  const double A = 0.01, T = 0.5, w = 2.0 * M_PI / T; // x = X + A sin(w t) e_x
  const std::vector<std::string> domain = {
      "fluid.domain={min: [-0.2, -0.2, -0.2], max: [0.4, 0.6, 0.4]}"};
  std::vector<std::string> moved = domain;
  moved.push_back("fluid.tank_motion={kind: sinusoid, dof: x, amplitude: 0.01, period: 0.5}");
  emps_plugin::EmpsModel3 still(load_scene(kScene, domain)), moving(load_scene(kScene, moved));
  const int steps = 10; // 5 ms: sound at 15 m/s crosses 0.075 m of the 0.2 m tank
  advance(still, 0, steps);
  advance(moving, 0, steps);
  const double t = steps * kDt, shift = A * std::sin(w * t);
  const auto &X = still.walls().nodes().x, &x = moving.walls().nodes().x;
  REQUIRE(X.size() == x.size());
  for (std::size_t k = 0; k < X.size(); ++k) {
    CHECK((x[k] - X[k] - shift * Vec3::UnitX()).norm() < 1e-15);
    CHECK((moving.walls().nodes().v[k] - A * w * std::cos(w * t) * Vec3::UnitX()).norm() < 1e-15);
  }
  // Mean pressure of the particles within 2 l0 of the wall x = 0 (side -1) or x = 0.2 (side +1),
  // in the tank's frame.
  const auto beside = [](const emps_plugin::EmpsModel3& m, double offset, int side) {
    const auto& p = m.fluid().particles();
    double sum = 0.0;
    int count = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const double xi = p.position[0][i] - offset;
      if (side < 0 ? xi < 0.04 : xi > 0.16) sum += p.p[i], ++count;
    }
    return sum / count;
  };
  const double rho_c_v = 1000.0 * 15.0 * A * w; // the pressure of a piston at speed A w
  const double rise = beside(moving, shift, -1) - beside(still, 0.0, -1);
  const double fall = beside(moving, shift, 1) - beside(still, 0.0, 1);
  INFO("beside the wall moving in " << rise / rho_c_v << " rho c v, moving away " << fall / rho_c_v
                                    << " rho c v");
  // A piston raises p by rho c v (acoustics); the drop behind the receding wall is cut where
  // particles' pnd falls below beta n0 (p = 0 there, eq. 17), so it is asserted by sign only,
  // with a margin far above round-off (the runs differ by the motion alone).
  CHECK(rise > 0.5 * rho_c_v);
  CHECK(fall < -0.02 * rho_c_v);
  CHECK(probe(moving, "wall_gap") > 0.0);
  CHECK(probe(moving, "particles") == 1000.0);
}

TEST_CASE("apps: what a 3-D EMPS scene does not have yet, and bad tanks, are refused by name",
          "[apps][emps][3d]") {
  const auto dir = std::filesystem::temp_directory_path();
  const std::string flipped = (dir / "test_emps_plugin_3d_flipped.stl").string();
  const std::string broken = (dir / "test_emps_plugin_3d_broken.stl").string();
  { // the shipped tank with every facet's vertex order and normal reversed: facing out
    std::ifstream in(FSI_SOURCE_DIR "/data/meshes/hydrostatic_tank_emps_3d.stl");
    std::ofstream out(flipped);
    std::string line, a, b;
    while (std::getline(in, line)) {
      if (line.find("facet normal") != std::string::npos) {
        std::istringstream n(line.substr(line.find("normal") + 6));
        double x, y, z;
        n >> x >> y >> z;
        out << "facet normal " << -x << ' ' << -y << ' ' << -z << '\n';
      } else if (line.find("vertex") != std::string::npos) {
        if (a.empty())
          a = line;
        else if (b.empty())
          b = line;
        else
          out << line << '\n' << b << '\n' << a << '\n', a.clear(), b.clear();
      } else
        out << line << '\n';
    }
    std::ofstream(broken) << "solid t\n  facet normal 0 0 1\n    outer loop\n      vertex 0 0\n";
  }
  // (the scene, overrides, what the one-line message says after "FILE:LINE: ")
  const std::vector<std::tuple<std::string, std::vector<std::string>, std::string>> bad = {
      {kScene,
       {"fluid.wall_contact=viscous"},
       "fluid.wall_contact: 'viscous' is not available in 3-D yet"},
      {kScene,
       {"fluid.wall_pressure=neighbours"},
       "fluid.wall_pressure: 'neighbours' is not available in 3-D yet"},
      {kScene,
       {"fluid.tank_file=../meshes/hydrostatic_tank_emps_3d.stl"},
       "fluid.tank_file: give either tank (a box) or tank_file (a surface), not both"},
      {kStlScene, {"fluid.tank_file=no_such.stl"}, "fluid.tank_file: file not found"},
      {kStlScene,
       {"fluid.tank_file=" + flipped},
       flipped + ": the fluid at (0.01, 0.01, 0.01) m lies behind facet"},
      {kStlScene, {"fluid.tank_file=" + broken}, broken + ":4:"},
      {kScene,
       {"output.probes[4].point=[0.1, 0.01, 0.5]"},
       "output.probes[4].point: the point is outside the fluid domain"},
      {kScene,
       {"walls=[{name: w, polyline: [[0, 0], [1, 0]]}]"},
       "3-D wall polylines are not yet available"},
      {kScene,
       {"fluid.regions[0].max=[0.2, 0.2, 0.3]"},
       "fluid.regions: fluid region 0 reaches outside the tank"},
      {kScene,
       {"fluid.tank_motion={kind: sinusoid, dof: z, amplitude: 0.01, period: 0.5}"},
       "fluid.tank_motion: needs fluid.domain, a box that holds the tank as it moves"},
      {kScene,
       {"fluid.tank_motion={kind: table, dof: z, table: "
        "../ref/liao_dam_break_elastic_plate/gate_lift.csv, unit: rad}"},
       "fluid.tank_motion.unit: 'rad' does not match dof 'z'"},
      {kScene,
       {"fluid.tank_motion={kind: sinusoid, axis: [0, 0, 0], amplitude: 0.1, period: 0.5}"},
       "fluid.tank_motion.axis: is zero"}};
  for (const auto& [file, sets, what] : bad) {
    INFO(sets.front());
    CHECK_THROWS_AS(emps_plugin::EmpsModel3(load_scene(file, sets)), InputError);
    CHECK_THROWS_WITH(emps_plugin::EmpsModel3(load_scene(file, sets)), Catch::Contains(what));
  }
  std::filesystem::remove(flipped);
  std::filesystem::remove(broken);
}

namespace {

/// An ASCII STL of the octahedron |x - c|_1 = R (8 facets, normals out; `skip`: a facet left
/// out, an open surface) in the temporary folder.
std::string octahedron_stl(const std::string& name, const Vec3& c, double R, int skip = -1) {
  const std::string path = (std::filesystem::temp_directory_path() / name).string();
  std::ofstream out(path);
  out.precision(17);
  out << "solid octahedron\n";
  int k = 0;
  for (const double sx : {1.0, -1.0})
    for (const double sy : {1.0, -1.0})
      for (const double sz : {1.0, -1.0}) {
        if (k++ == skip) continue;
        Vec3 a = c + sx * R * Vec3::UnitX(), b = c + sy * R * Vec3::UnitY(),
             d = c + sz * R * Vec3::UnitZ();
        if (sx * sy * sz < 0) std::swap(b, d); // counter-clockwise seen from outside
        const Vec3 n = (b - a).cross(d - a).normalized();
        out << "facet normal " << n.x() << ' ' << n.y() << ' ' << n.z() << "\nouter loop\n";
        for (const Vec3& v : {a, b, d})
          out << "vertex " << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
        out << "endloop\nendfacet\n";
      }
  out << "endsolid octahedron\n";
  return path;
}

/// Process `rank` of `size` as mpirun would number it, for what reads only those (the fill).
class RankOf final : public Ranks {
public:
  RankOf(int rank, int size) : rank_(rank), size_(size) {}
  int rank() const override { return rank_; }
  int size() const override { return size_; }
  bool decomposed() const override { return true; }
  bool all(bool) const override { throw RunError("RankOf: no collectives"); }
  Agreed agree(int, const std::string&) const override { throw RunError("RankOf"); }
  std::string first(const std::string&) const override { throw RunError("RankOf"); }
  void gather(const std::vector<double>&, std::vector<double>&) const override {
    throw RunError("RankOf");
  }
  void exchange(const std::vector<double>&, const std::vector<int>&,
                std::vector<double>&) const override {
    throw RunError("RankOf");
  }
  void sum(std::vector<double>&) const override { throw RunError("RankOf"); }
  void broadcast(std::vector<double>&) const override { throw RunError("RankOf"); }

private:
  std::unique_ptr<particles::Decomposition<2>>
  new_decomposition(std::integral_constant<int, 2>) const override {
    throw RunError("RankOf");
  }
  std::unique_ptr<particles::Decomposition<3>>
  new_decomposition(std::integral_constant<int, 3>) const override {
    throw RunError("RankOf");
  }
  int rank_, size_;
};

} // namespace

TEST_CASE("apps: a 3-D EMPS fluid region given as a closed surface (fluid.region_file) holds its "
          "lattice count",
          "[apps][emps][3d]") {
  // |x - c|_1 < R = 4 l0 on the lattice c - R + (i + 1/2) l0: the odd triples (p, q, r) with
  // p + q + r < 8, 10 of them in each of the 8 octants (geometry_erp's fill).
  const double l0 = 0.02, R = 4 * l0;
  const Vec3 c(0.1, 0.3, 0.1); // above the shipped scene's box of water, inside its tank
  const std::string stl = octahedron_stl("test_emps_plugin_3d_octahedron.stl", c, R);
  SECTION("alone: 80 particles, all inside") {
    const Scene scene = load_scene(kScene, {"fluid.regions=[]", "fluid.region_file=" + stl});
    emps_plugin::EmpsModel3 model(scene);
    const auto& p = model.fluid().particles();
    REQUIRE(p.size() == 80);
    for (std::size_t i = 0; i < p.size(); ++i)
      CHECK((Vec3(p.position[0][i], p.position[1][i], p.position[2][i]) - c).cwiseAbs().sum() < R);
    // The footprint counts the enclosed volume 4/3 R^3 in l0^3, with convex_corners (the
    // default) 503 B more per particle: erp::ConvexFaces' 1 B, 3 pieces of 30 B (face, end, seed
    // triangle and point) and their wall forces' slots of 52 B, and 8 planes of 32 B.
    const Footprint with = emps_plugin::footprint3(scene);
    CHECK_THAT(with.count, Catch::Matchers::WithinRel(4.0 / 3.0 * 64.0, 1e-12));
    const Footprint without = emps_plugin::footprint3(load_scene(
        kScene, {"fluid.regions=[]", "fluid.region_file=" + stl, "fluid.convex_corners=false"}));
    CHECK_THAT(with.bytes - without.bytes, Catch::Matchers::WithinRel(503.0 * with.count, 1e-12));
    // The viscous wall terms' three slots of 52 B, counted only where a viscous wall term runs.
    const Footprint inviscid = emps_plugin::footprint3(
        load_scene(kScene, {"fluid.regions=[]", "fluid.region_file=" + stl, "fluid.viscosity=0",
                            "fluid.wall_approach_viscosity=0"}));
    CHECK_THAT(with.bytes - inviscid.bytes, Catch::Matchers::WithinRel(156.0 * with.count, 1e-12));
  }
  SECTION("beside the box of water: 1,080 particles, four steps with none lost") {
    emps_plugin::EmpsModel3 model(load_scene(kScene, {"fluid.region_file=" + stl}));
    CHECK(model.fluid().particles().size() == 1080);
    advance(model, 0, 4);
    CHECK(probe(model, "particles") == 1080.0);
    CHECK(probe(model, "wall_gap") > 0.0);
  }
  SECTION("each rank's block of the fill is its slice of the whole, built without the rest") {
    // Two overlapping boxes (the second's points in the first left out) and the surface's
    // points outside both (ids after the boxes'): on P ranks each builds ids
    // [n r/P, n(r+1)/P) only, and the blocks in rank order are the one-process fill, bit for bit.
    const Scene scene = load_scene(
        kScene, {"fluid.region_file=" + stl,
                 "fluid.regions=[{min: [0, 0, 0], max: [0.2, 0.2, 0.2]}, {min: [0.05, 0.15, "
                 "0.05], max: [0.15, 0.25, 0.15]}]"});
    const auto& f = scene.fluid->as<emps_plugin::FluidSpec3>();
    const Fill3 whole = emps_plugin::fill_regions3(f, OneProcess());
    REQUIRE(whole.total == whole.x.size());
    REQUIRE(whole.total > 1080); // the box and the octahedron of the section above, and more
    for (int P = 1; P <= 4; ++P) {
      std::vector<Vec3> joined;
      for (int r = 0; r < P; ++r) {
        const Fill3 block = emps_plugin::fill_regions3(f, RankOf(r, P));
        CHECK(block.total == whole.total);
        CHECK(block.ids.first == joined.size());
        CHECK(block.x.size() == block.ids.size());
        joined.insert(joined.end(), block.x.begin(), block.x.end());
      }
      CHECK(joined == whole.x);
    }
  }
  SECTION("an open surface is refused naming the key and the file") {
    const std::string open = octahedron_stl("test_emps_plugin_3d_open.stl", c, R, 3);
    CHECK_THROWS_WITH(emps_plugin::EmpsModel3(load_scene(kScene, {"fluid.region_file=" + open})),
                      Catch::Contains("fluid.region_file: " + open +
                                      ": 3 edges with one facet (a fluid region must be a "
                                      "closed surface)"));
    std::filesystem::remove(open);
  }
  SECTION("a surface outside the domain is refused") {
    CHECK_THROWS_WITH(emps_plugin::EmpsModel3(load_scene(
                          kScene, {"fluid.region_file=" + stl,
                                   "fluid.domain={min: [0, 0, 0], max: [0.2, 0.25, 0.2]}"})),
                      Catch::Contains("fluid.domain: the region_file surface reaches outside the "
                                      "domain"));
  }
  SECTION("a surface outside the tank, a box or tank_file's bounding box, is refused") {
    // Moved to z = 0.19 the octahedron reaches z = 0.27, past both tanks' z = 0.2.
    const std::string out = octahedron_stl("test_emps_plugin_3d_out.stl", {0.1, 0.3, 0.19}, R);
    const std::string domain = "fluid.domain={min: [-0.1, -0.1, -0.1], max: [0.4, 0.6, 0.4]}";
    for (const std::string& scene : {kScene, kStlScene}) {
      INFO(scene);
      CHECK_NOTHROW(load_scene(scene, {"fluid.region_file=" + stl, domain}));
      CHECK_THROWS_WITH(load_scene(scene, {"fluid.region_file=" + out, domain}),
                        Catch::Contains("fluid.region_file: the surface reaches outside the tank"));
    }
    std::filesystem::remove(out);
  }
  std::filesystem::remove(stl);
}
