#pragma once
// The parsers the fuzz targets drive, shared with the regression test of the inputs they found.
// Each returns the InputError message, or "" when the input parses; anything else escapes.
#include <string>

namespace fsi::fuzz {

/// The whole text is a scene file (named `fuzz/scene.yaml`), read and validated (with the
/// resource check).
std::string scene_input(const std::string& text);

/// Each line is one `--set` argument, applied to data/scenes/dam_break_elastic_obstacle.yaml.
std::string override_input(const std::string& text);

/// The whole text is a mesh file (named `fuzz.msh`), read as a 2-D (T6) and a 3-D (T10) Gmsh
/// mesh and as an STL surface: the first message that is not well formed (3-D, then STL), else
/// the 2-D reader's.
std::string gmsh_input(const std::string& text);

/// Whether `message` (from one of the above; `target` is scene, override or gmsh) is empty or one
/// line `FILE:LINE: KEY: what` (scene), `FILE:LINE: what` or `FILE: what` for a whole-file
/// problem (gmsh), or naming the `--set` argument (override).
bool well_formed(const std::string& target, const std::string& message);

} // namespace fsi::fuzz
