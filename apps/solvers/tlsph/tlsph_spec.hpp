#pragma once
// The TL-SPH solid's scene entry (structures[].type: tlsph), as the plug-in reads it.
#include "fsi_app/scene.hpp"
#include "fsi_app/scene_reader.hpp"
#include "materials/material.hpp"

#include <memory>
#include <string>
#include <vector>

namespace fsi::app::tlsph_plugin {

struct Box {
  Vec2 min = Vec2::Zero(), max = Vec2::Zero();
};

struct TlsphSpec final : SolverSpec {
  Box region;                          ///< the rectangle filled with particles (sides tagged
                                       ///< bottom, right, top, left)
  double dp = 0.0;                     ///< particle spacing dp_S, m
  double h_factor = 1.15;              ///< h = h_factor dp
  materials::MaterialOptions material; ///< the keys materials/ declares
  std::vector<Box> clamped;            ///< particles with X0 inside a box are held (or moved)
  std::string clamped_motion;          ///< wall whose rigid motion the clamped particles follow
  std::vector<std::string> interface;  ///< sides wetted by the fluid
  double pair_damping = 0.0, mass_damping = 0.0;
};

/// Reads the keys of one structures entry (type and name excepted) into a TlsphSpec.
std::shared_ptr<const SolverSpec> read_tlsph(Section& s);

} // namespace fsi::app::tlsph_plugin
