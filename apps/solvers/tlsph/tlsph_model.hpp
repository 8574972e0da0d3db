#pragma once
// The TL-SPH solid of one scene entry (structures[].type: tlsph): particles filling its region,
// clamped boxes (fixed or following a wall's motion), gravity and, coupled, the interface loads
// on its surface particles; also the coupler's S through the interface those particles describe.
#include "fsi_app/solver_plugin.hpp"
#include "fsi_app/wall_motion.hpp"
#include "solid_tlsph/solid.hpp"
#include "tlsph/tlsph_adapter.hpp"
#include "tlsph/tlsph_spec.hpp"

#include <memory>
#include <optional>

namespace fsi::app::tlsph_plugin {

class TlsphModel final : public StructurePart {
public:
  /// Throws InputError (scene file and line) for options the solver refuses.
  TlsphModel(const Scene& scene, const StructureBlock& block);
  void advance(double time, double dt) override;
  /// The particles as a point grid named after the structure.
  void write_frame(FieldsFile& file, const std::vector<std::string>& fields) const override;
  /// displacement_x|y at the probe's point: its nearest particle's, or the kernel interpolation
  /// (interpolate: true); displacement_x|y_tank: the same in the clamped_motion wall's frame.
  std::optional<double> probe(const ProbeSpec& probe) const override;
  std::optional<std::string> non_finite() const override;
  void report(JsonObject& run) const override;
  /// The solid and its counters under "structures/<name>/".
  void write_state(StateArchive& archive) const override;
  void read_state(const StateArchive& archive) override;
  const InterfaceMesh& interface_mesh() const override { return interface_; }
  std::vector<Polygon> occupied_area() const override;
  coupling::StructureSolver& coupling_solver() override { return adapter_; }

  tlsph::TlsphSolid& solid() { return *solid_; }

private:
  std::vector<Vec2> outline_;
  std::unique_ptr<tlsph::TlsphSolid> solid_;
  InterfaceMesh interface_;
  struct Probe {
    std::string name;
    tlsph::ProbeStencil stencil;
    Vec2 X; // the reference position the stencil samples
  };
  std::vector<Probe> probes_;
  std::optional<WallFrame> frame_; // the clamped_motion wall's motion (tank-frame probes)
  TlsphAdapter<2, TlsphModel> adapter_{*this};
  long steps_ = 0, substeps_ = 0;
  mutable std::vector<double> xy_, u_, v_; // output buffers
};

} // namespace fsi::app::tlsph_plugin
