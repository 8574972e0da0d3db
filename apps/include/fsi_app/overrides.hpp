#pragma once
// `--set key.path=value`: replaces (or adds) one entry of the scene tree before validation.
#include "fsi_app/scene_reader.hpp"

#include <string>
#include <yaml-cpp/yaml.h>

namespace fsi::app {

/// Applies `text` (`a.b[2].c=value`, value in YAML syntax) to `root` and records the path in
/// ctx.overrides so later messages name the override. Throws InputError on a malformed override.
void apply_override(YAML::Node& root, const std::string& text, ReadContext& ctx);

} // namespace fsi::app
