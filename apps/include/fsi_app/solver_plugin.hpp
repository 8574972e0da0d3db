#pragma once
// Solver plug-ins: how a fluid or structure solver joins a scene. Each solver has one folder,
// apps/solvers/<name>/, that declares its scene keys once (read), builds its model and coupling
// adapter (build), and names its output fields, probe quantities and memory estimate; the
// registration list in apps/solvers/registry.cpp is the one place that names them all. The rest
// of apps/ (scene reader, run driver, coupled model) knows only these interfaces.
#include "coupling/interface.hpp"
#include "fsi/core/interface_mesh.hpp"
#include "fsi_app/model.hpp"
#include "fsi_app/scene.hpp"
#include "fsi_app/scene_reader.hpp"

#include <functional>
#include <memory>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace fsi::app {

using Polygon = std::vector<Vec2>;

/// A fluid in a run: stand-alone (the Model interface) and, in a coupled scene, the coupler's F.
class FluidPart : public Model {
public:
  /// F against the interfaces the part was built with, their nodes concatenated in the order
  /// given (coupling/interface.hpp).
  virtual coupling::FluidSolver& coupling_solver() = 0;
  /// The fluid's force on the coupled structures (all of them; on every wall without one) of the
  /// last step, N/m, split into the terms that carry it (e.g. pressure, repulsive, viscous), so
  /// that coupling.csv shows what carries the load. Names are fixed for the part's lifetime.
  virtual std::vector<std::pair<std::string, Vec2>> force_parts() const { return {}; }
  /// The 3-D F (a part built by FluidPlugin::build3) against the interfaces it was built with,
  /// their nodes concatenated in the order given. Default: throws std::logic_error naming the
  /// part (a fluid without 3-D coupling).
  virtual coupling::FluidSolver3& coupling_solver3();
};

/// A structure in a run: stand-alone, or the coupler's S through the interface it describes.
class StructurePart : public Model {
public:
  explicit StructurePart(std::string name) : name_(std::move(name)) {}
  /// The structure's name in the scene (structures[].name).
  const std::string& name() const { return name_; }
  /// The coupling interface (its wetted boundary), in the reference configuration.
  virtual const InterfaceMesh& interface_mesh() const = 0;
  /// The area the structure occupies, kept free of fluid particles.
  virtual std::vector<Polygon> occupied_area() const = 0;
  virtual coupling::StructureSolver& coupling_solver() = 0;
  /// The 3-D coupling interface (triangular faces), in the reference configuration, and the 3-D
  /// S through it. Defaults: throw std::logic_error naming the structure (no 3-D coupling).
  virtual const InterfaceMesh3& interface_mesh3() const;
  virtual coupling::StructureSolver3& coupling_solver3();

private:
  std::string name_;
};

/// Memory a part needs, for the up-front check (apps/src/resources.cpp).
struct Footprint {
  double bytes = 0.0;
  double count = 0.0; ///< particles, elements: what sets the size
  std::string key;    ///< the key of the part's block that sets it, e.g. "l0"
  std::string counts; ///< what was counted, for the message ("20000 particles (...)")
  /// Counts that exceed the solver's index types: (key, message).
  std::vector<std::pair<std::string, std::string>> overflows;
};

/// What a structure shows the fluid before the run: its coupling interface and the area it
/// occupies, as its part would give them.
struct StructureOutline {
  InterfaceMesh interface;
  std::vector<Polygon> occupied;
  InterfaceMesh3 interface3 = {}; ///< a 3-D scene's (StructurePart::interface_mesh3)
};

/// A plug-in's functions and names, in this order (each plug-in's plugin() lists them so).
struct FluidPlugin {
  std::string name, doc;
  /// Reads the solver's own keys of the fluid block (every key declared there, once).
  std::function<std::shared_ptr<const SolverSpec>(Section&)> read;
  /// Cross-checks against the whole scene (after every block is read); `probes` are the probes'
  /// blocks, for messages about them.
  std::function<void(const Scene&, Section&, std::vector<Section>& probes)> check;
  /// interfaces: the coupled structures' interfaces (empty for a fluid alone); solid: the areas
  /// they occupy; ranks: the processes the part will be decomposed over (Model::decompose), so
  /// that each builds only its share of the fluid (one process: OneProcess).
  std::function<std::unique_ptr<FluidPart>(const Scene&, const std::vector<InterfaceMesh>&,
                                           const std::vector<Polygon>&, const Ranks&)>
      build;
  /// The input checks `build` makes (e.g. that particles fit the regions), without building the
  /// solver: `fsi check` (seconds and megabytes where build takes minutes and gigabytes).
  std::function<void(const Scene&, const std::vector<InterfaceMesh>&, const std::vector<Polygon>&)>
      validate;
  std::function<Footprint(const Scene&)> footprint;
  std::vector<std::string> fields;           ///< output fields it writes
  std::vector<std::string> probe_quantities; ///< probes it answers (without a `structure`)
  /// A 3-D coupled scene's fluid (scene.dimension 3 with structures): interfaces as `build`'s,
  /// the structures' InterfaceMesh3 in scene order, ranks as `build`'s. Empty: the type has no
  /// 3-D coupling (the scene reader refuses such a scene at fluid.type).
  std::function<std::unique_ptr<FluidPart>(const Scene&, const std::vector<InterfaceMesh3>&,
                                           const Ranks&)>
      build3 = {};
  /// The input checks build3 makes, without building the solver (`fsi check`); empty: none
  /// beyond `validate`'s.
  std::function<void(const Scene&, const std::vector<InterfaceMesh3>&)> validate3 = {};
};

/// As FluidPlugin: the functions and names in this order.
struct StructurePlugin {
  std::string name, doc;
  std::function<std::shared_ptr<const SolverSpec>(Section&)> read;
  /// Cross-checks of entry `index` against the whole scene (probes naming it, walls it follows).
  std::function<void(const Scene&, std::size_t index, Section&, std::vector<Section>& probes)>
      check;
  std::function<std::unique_ptr<StructurePart>(const Scene&, std::size_t index)> build;
  /// The input checks `build` makes of entry `index` (its mesh file, boundary tags, probe nodes)
  /// without building the solver, and the outline its part would show: `fsi check`.
  std::function<StructureOutline(const Scene&, std::size_t index)> validate;
  std::function<Footprint(const Scene&, std::size_t index)> footprint;
  std::vector<std::string> fields;
  std::vector<std::string> probe_quantities; ///< probes naming a structure of this type
  /// Before `read`, when the entry gives another type's geometry and not this type's: rewrites
  /// the entry (Section::rebind) into this type's keys (apps/solvers/structure_geometry.hpp);
  /// empty: none.
  std::function<void(Section&)> adopt;
};

/// `build` of a part whose constructor takes what build is given.
template <class Part>
std::unique_ptr<FluidPart> make_fluid_part(const Scene& scene,
                                           const std::vector<InterfaceMesh>& interfaces,
                                           const std::vector<Polygon>& solid, const Ranks& ranks) {
  return std::make_unique<Part>(scene, interfaces, solid, ranks);
}
template <class Part>
std::unique_ptr<StructurePart> make_structure_part(const Scene& scene, std::size_t index) {
  return std::make_unique<Part>(scene, scene.structures[index]);
}

/// The registration lists (apps/solvers/registry.cpp), in registration order; the first entry
/// is the default type.
const std::vector<FluidPlugin>& fluid_plugins();
const std::vector<StructurePlugin>& structure_plugins();
/// Adds a plug-in after the built-in ones (a solver of one's own, e.g. a test's stand-in), before
/// any scene is read; it then takes part in reading, the reference and building like the others.
void add_fluid_plugin(FluidPlugin plugin);
void add_structure_plugin(StructurePlugin plugin);
/// The top-level keys a plug-in's `read` declares (read in documentation mode).
std::set<std::string>
declared_keys(const std::function<std::shared_ptr<const SolverSpec>(Section&)>& read);
/// By name; nullptr for an unknown name.
const FluidPlugin* find_fluid_plugin(std::string_view name);
const StructurePlugin* find_structure_plugin(std::string_view name);

} // namespace fsi::app
