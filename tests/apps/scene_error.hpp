#pragma once
// The one-line InputError message of a scene that is refused ("" when it loads): the check of
// the tests of bad input.
#include "fsi/core/error.hpp"
#include "fsi_app/scene.hpp"

#include <string>
#include <vector>

namespace fsi::app::test {

/// The message of load_scene(file, overrides), "" if it loads.
inline std::string scene_file_error(const std::string& file,
                                    const std::vector<std::string>& overrides) {
  try {
    load_scene(file, overrides);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

/// The message of parse_scene(text, name, overrides), "" if it parses.
inline std::string scene_text_error(const std::string& text, const std::string& name = "scene.yaml",
                                    const std::vector<std::string>& overrides = {}) {
  try {
    parse_scene(text, name, overrides);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

} // namespace fsi::app::test
