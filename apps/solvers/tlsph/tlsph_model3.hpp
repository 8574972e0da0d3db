#pragma once
// The TL-SPH solid of one entry of a 3-D scene (dimension: 3, structures[].type: tlsph): a box
// filled with particles (tlsph::fill_box), fixed clamped boxes (odd images at their faces),
// gravity; its interface, order-1 triangles over the box faces `interface` names (left, right,
// bottom, top, back, front: x-, x+, y-, y+, z-, z+), and the coupler's S on it (TlsphAdapter<3>).
// The plug-in API (StructurePart) is 2-D: the part shows no 2-D interface or area, and a 3-D
// fluid couples through interface_mesh3() and coupling_solver3().
#include "fsi_app/solver_plugin.hpp"
#include "solid_tlsph/solid.hpp"
#include "tlsph/tlsph_adapter.hpp"
#include "tlsph/tlsph_spec.hpp"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace fsi::app::tlsph_plugin {

class TlsphModel3 final : public StructurePart {
public:
  /// Throws InputError (scene file and line) for options or probes the solver refuses.
  TlsphModel3(const Scene& scene, const StructureBlock& block);
  void advance(double time, double dt) override;
  /// The particles as a point grid (x, y, z) named after the structure.
  void write_frame(FieldsFile& file, const std::vector<std::string>& fields) const override;
  /// displacement_x|y|z at the probe's point3: its nearest particle's, or the kernel
  /// interpolation (interpolate: true).
  std::optional<double> probe(const ProbeSpec& probe) const override;
  std::optional<std::string> non_finite() const override;
  void report(JsonObject& run) const override;
  /// The solid and its counters under "structures/<name>/".
  void write_state(StateArchive& archive) const override;
  void read_state(const StateArchive& archive) override;
  const InterfaceMesh& interface_mesh() const override { return no_interface_; }
  std::vector<Polygon> occupied_area() const override { return {}; }
  /// The 2-D S: throws std::logic_error (a 3-D structure's S is coupling_solver3()).
  coupling::StructureSolver& coupling_solver() override;

  /// The tagged box faces' triangles, each node on a particle (tlsph::TlsphSolid3::interface_mesh).
  const InterfaceMesh3& interface_mesh3() const override { return interface3_; }
  /// The coupler's S (eq. 67) on the solid through interface_mesh3().
  coupling::StructureSolver3& coupling_solver3() override { return adapter_; }

  tlsph::TlsphSolid3& solid() { return *solid_; }

private:
  std::unique_ptr<tlsph::TlsphSolid3> solid_;
  InterfaceMesh no_interface_;
  InterfaceMesh3 interface3_;
  std::vector<std::pair<std::string, tlsph::ProbeStencil>> probes_;
  TlsphAdapter<3, TlsphModel3> adapter_{*this};
  long steps_ = 0, substeps_ = 0;
  mutable std::vector<double> xyz_, u_, v_; // output buffers
};

} // namespace fsi::app::tlsph_plugin
