#pragma once
// A structure alone (no fluid): the T6 FEM solid under gravity and the scene's constant loads.
#include "fsi_app/model.hpp"
#include "geometry_erp/motion.hpp"
#include "structure_fem/structure.hpp"

#include <memory>
#include <optional>

namespace fsi::app {

/// The FEM structure of one scene entry: mesh built, options mapped, probes resolved to nodes.
/// Throws InputError (scene file and line) for tags, probes or meshes that do not fit.
std::unique_ptr<fem::Structure> build_structure(const Scene& scene, const StructureSpec& spec);

/// The moving frame a structure is clamped in (its clamped_motion wall): that wall's rigid motion
/// about its pivot.
struct TankFrame {
  std::shared_ptr<const erp::Motion> motion;
  Vec2 pivot;
};

/// The frame of the structure's clamped_motion wall, or nullopt if it is clamped in place.
std::optional<TankFrame> tank_frame(const Scene& scene, const StructureSpec& spec);

/// The area the mesh occupies, for a fluid to keep free of particles: each element's corner
/// triangle.
std::vector<std::vector<Vec2>> occupied_area(const fem::Mesh& mesh);

/// The FE node a displacement probe names (by index, or by reference position).
int probe_node(const Scene& scene, const fem::Mesh& mesh, const ProbeSpec& probe);

class StructureModel final : public Model {
public:
  StructureModel(const Scene& scene, const StructureSpec& spec);
  void advance(double time, double dt) override;
  void declare(FieldsFile& file) const override;
  void write_frame(FieldsFile& file, const std::vector<std::string>& fields) const override;
  std::optional<double> probe(const ProbeSpec& probe) const override;
  void report(JsonObject& run) const override;
  void write_state(StateArchive& archive) const override;
  void read_state(const StateArchive& archive) override;

  fem::Structure& structure() { return *structure_; }

private:
  std::string name_;
  std::unique_ptr<fem::Structure> structure_;
  std::optional<TankFrame> frame_; // the clamped_motion wall's motion (tank-frame probes)
  std::vector<std::pair<std::string, int>> probe_nodes_; // probe name -> node
  long newton_iterations_ = 0, steps_ = 0;
  int newton_max_ = 0;
  long newton_halvings_ = 0, steps_with_halvings_ = 0; ///< Newton safeguard (Structure::newton)
  long substepped_steps_ = 0, substeps_ = 0;           ///< retried steps, their sub-steps
};

} // namespace fsi::app
