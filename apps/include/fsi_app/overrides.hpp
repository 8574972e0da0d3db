#pragma once
// `--set key.path=value`: replaces (or adds) one entry of the scene tree before validation.
#include "fsi_app/scene_reader.hpp"

#include <functional>
#include <string>
#include <vector>
#include <yaml-cpp/yaml.h>

namespace fsi::app {

/// Applies `text` (`a.b[2].c=value`, value in YAML syntax) to `root` and records the path in
/// ctx.overrides so later messages name the override. Throws InputError on a malformed override.
void apply_override(YAML::Node& root, const std::string& text, ReadContext& ctx);

/// Before any override applies: each node on each override's path becomes its parent's own, a
/// copy taken from `reparse()` (the scene's tree as read, with its lines), so that an override
/// through a YAML alias changes only the node it names (issue 41). Malformed overrides are left
/// to apply_override.
void unshare_override_paths(YAML::Node& root, const std::vector<std::string>& overrides,
                            const std::function<YAML::Node()>& reparse);

} // namespace fsi::app
