#pragma once
// The TL-SPH solid of one entry of a 3-D scene (dimension: 3, structures[].type: tlsph): a box
// filled with particles (tlsph::fill_box), fixed clamped boxes (odd images at their faces),
// gravity. 3-D scenes take no fluid for it yet, so the part is never coupled: it shows no 2-D
// interface and occupies no 2-D area.
#include "fsi_app/solver_plugin.hpp"
#include "solid_tlsph/solid.hpp"
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
  /// Never called: a 3-D TL-SPH solid is not coupled (throws std::logic_error).
  coupling::StructureSolver& coupling_solver() override;

private:
  std::unique_ptr<tlsph::TlsphSolid3> solid_;
  InterfaceMesh no_interface_;
  std::vector<std::pair<std::string, tlsph::ProbeStencil>> probes_;
  long steps_ = 0, substeps_ = 0;
  mutable std::vector<double> xyz_, u_, v_; // output buffers
};

} // namespace fsi::app::tlsph_plugin
