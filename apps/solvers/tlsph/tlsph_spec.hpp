#pragma once
// The TL-SPH solid's scene entry (structures[].type: tlsph), as the plug-in reads it.
#include "fsi_app/scene.hpp"
#include "fsi_app/scene_reader.hpp"
#include "solid_tlsph/solid.hpp"

#include <memory>
#include <string>
#include <vector>

namespace fsi::app::tlsph_plugin {

struct Box {
  Vec2 min = Vec2::Zero(), max = Vec2::Zero();
};
struct Box3 {
  Vec3 min = Vec3::Zero(), max = Vec3::Zero();
};

struct TlsphSpec final : SolverSpec {
  tlsph::TlsphOptions options;   ///< the keys solid_tlsph and materials/ declare, the wetted sides
  std::vector<Vec2> outline;     ///< the region, counter-clockwise, filled with particles
  std::vector<std::string> tags; ///< a tag per outline edge (rectangle: bottom, right, top, left)
  std::vector<Box> clamped;      ///< particles with X0 inside a box are clamped (or moved)
  std::string clamped_motion;    ///< wall whose rigid motion the clamped particles follow
  Box3 box;                      ///< 3-D: the region, a box filled with particles at dp
  std::vector<Box3> clamped3;    ///< 3-D: the clamped boxes
};

/// Reads the keys of one structures entry (type and name excepted) into a TlsphSpec.
std::shared_ptr<const SolverSpec> read_tlsph(Section& s);

} // namespace fsi::app::tlsph_plugin
