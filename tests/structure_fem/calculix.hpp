#pragma once
// Runs CalculiX (ccx) on a deck and reads nodal displacements; the deck of a T6 mesh as CPE6
// plane-strain elements.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unistd.h>

#include "structure_fem/mesh.hpp"

namespace fem_test {

/// True if an executable `ccx` is on PATH.
inline bool ccx_available() {
  const char* path = std::getenv("PATH");
  if (!path) return false;
  std::stringstream dirs(path);
  for (std::string dir; std::getline(dirs, dir, ':');) {
    const auto exe = std::filesystem::path(dir) / "ccx";
    std::error_code ec;
    if (std::filesystem::is_regular_file(exe, ec) &&
        (std::filesystem::status(exe, ec).permissions() & std::filesystem::perms::owner_exec) !=
            std::filesystem::perms::none)
      return true;
  }
  return false;
}

struct CcxProblem {
  const fsi::fem::Mesh* mesh;
  double E, nu;
  std::vector<int> fixed; ///< nodes with u = 0
  fsi::fem::Vector f;     ///< nodal forces, size 2 * nodes
  std::vector<int> print; ///< nodes whose displacements are wanted
  double density = 0.0;   ///< with gravity_y != 0: the body force rho g (*DLOAD GRAV)
  double gravity_y = 0.0; ///< g along y [m/s^2]
};

/// Writes the deck `inp` as job.inp in a fresh directory under the system temp dir, runs
/// `ccx -i job` there and parses the *NODE PRINT block of job.dat. Returns node (0-based) ->
/// (u_x, u_y, u_z).
inline std::map<int, fsi::Vec3> run_ccx_deck(const std::string& inp, const std::string& name) {
  namespace fs = std::filesystem;
  const fs::path dir =
      fs::temp_directory_path() / ("fsi_ccx_" + name + "_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "job.inp") << inp;
  const std::string cmd = "cd '" + dir.string() + "' && ccx -i job > ccx.log 2>&1";
  if (std::system(cmd.c_str()) != 0)
    throw std::runtime_error("ccx failed; see " + (dir / "ccx.log").string());
  std::ifstream dat(dir / "job.dat");
  std::map<int, fsi::Vec3> u;
  bool in_block = false;
  for (std::string line; std::getline(dat, line);) {
    if (line.find("displacements") != std::string::npos) {
      in_block = true;
      continue;
    }
    if (!in_block) continue;
    std::istringstream s(line);
    int node = 0;
    double ux = 0, uy = 0, uz = 0;
    if (s >> node >> ux >> uy >> uz) u[node - 1] = {ux, uy, uz};
  }
  if (u.empty()) throw std::runtime_error("no displacements in " + (dir / "job.dat").string());
  fs::remove_all(dir);
  return u;
}

/// The deck of a CcxProblem (CPE6, unit thickness, *STATIC) run by run_ccx_deck. Returns node ->
/// (u_x, u_y).
inline std::map<int, fsi::Vec2> run_ccx_static(const CcxProblem& p, const std::string& name) {
  std::ostringstream inp;
  inp.precision(17);
  inp << "*NODE\n";
  for (std::size_t k = 0; k < p.mesh->num_nodes(); ++k)
    inp << k + 1 << ", " << p.mesh->X[k].x() << ", " << p.mesh->X[k].y() << ", 0\n";
  inp << "*ELEMENT, TYPE=CPE6, ELSET=EALL\n"; // same node order as ours
  for (std::size_t e = 0; e < p.mesh->num_elements(); ++e) {
    inp << e + 1;
    for (int n : p.mesh->elements[e]) inp << ", " << n + 1;
    inp << "\n";
  }
  inp << "*NSET, NSET=FIX\n";
  for (int n : p.fixed) inp << n + 1 << ",\n";
  inp << "*NSET, NSET=OUT\n";
  for (int n : p.print) inp << n + 1 << ",\n";
  inp << "*BOUNDARY\nFIX, 1, 2\n";
  inp << "*MATERIAL, NAME=SOLID\n*ELASTIC\n" << p.E << ", " << p.nu << "\n";
  if (p.gravity_y != 0.0) inp << "*DENSITY\n" << p.density << "\n";
  inp << "*SOLID SECTION, ELSET=EALL, MATERIAL=SOLID\n1.0\n"; // unit thickness
  inp << "*STEP\n*STATIC\n";
  if (p.gravity_y != 0.0)
    inp << "*DLOAD\nEALL, GRAV, " << std::abs(p.gravity_y) << ", 0., "
        << (p.gravity_y < 0.0 ? -1 : 1) << ", 0.\n";
  inp << "*CLOAD\n";
  for (std::size_t k = 0; k < p.mesh->num_nodes(); ++k)
    for (int c = 0; c < 2; ++c)
      if (p.f[static_cast<Eigen::Index>(2 * k) + c] != 0.0)
        inp << k + 1 << ", " << c + 1 << ", " << p.f[static_cast<Eigen::Index>(2 * k) + c] << "\n";
  inp << "*NODE PRINT, NSET=OUT\nU\n*END STEP\n";
  std::map<int, fsi::Vec2> u;
  for (const auto& [node, u3] : run_ccx_deck(inp.str(), name)) u[node] = u3.head<2>();
  return u;
}

} // namespace fem_test
