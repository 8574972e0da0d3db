#include "inputs.hpp"

#include "fsi/core/error.hpp"
#include "fsi_app/scene.hpp"
#include "geometry_erp/stl_reader.hpp"
#include "structure_fem/gmsh_reader.hpp"

#include <cctype>
#include <fstream>
#include <iterator>
#include <sstream>
#include <vector>

namespace fsi::fuzz {

namespace {

const std::filesystem::path kBaseScene =
    FSI_SOURCE_DIR "/data/scenes/dam_break_elastic_obstacle.yaml";

std::string base_scene_text() {
  std::ifstream in(kBaseScene, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

template <class Parse> std::string message_of(Parse parse) {
  try {
    parse();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

} // namespace

std::string scene_input(const std::string& text) {
  return message_of([&] { app::parse_scene(text, "fuzz/scene.yaml", {}); });
}

std::string override_input(const std::string& text) {
  static const std::string base = base_scene_text();
  std::vector<std::string> overrides;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) overrides.push_back(line);
  return message_of([&] { app::parse_scene(base, kBaseScene, overrides); });
}

std::string gmsh_input(const std::string& text) {
  const std::string t6 = message_of([&] {
    std::istringstream in(text);
    fem::read_gmsh(in, "fuzz.msh");
  });
  const std::string t10 = message_of([&] {
    std::istringstream in(text);
    fem::read_gmsh_t10(in, "fuzz.msh");
  });
  const std::string stl = message_of([&] {
    std::istringstream in(text);
    erp::read_stl(in, "fuzz.msh");
  });
  const std::string surface = message_of([&] {
    std::istringstream in(text);
    fem::read_gmsh_surface(in, "fuzz.msh");
  });
  if (!well_formed("gmsh", t10)) return t10;
  if (!well_formed("gmsh", surface)) return surface;
  return well_formed("gmsh", stl) ? t6 : stl;
}

namespace {

// `prefix` followed by `:LINE: ` (LINE digits); returns the position after it, or npos.
std::size_t after_line(const std::string& m, const std::string& prefix) {
  if (m.rfind(prefix + ":", 0) != 0) return std::string::npos;
  std::size_t i = prefix.size() + 1, digits = 0;
  while (i < m.size() && std::isdigit(static_cast<unsigned char>(m[i]))) ++i, ++digits;
  return digits > 0 && m.compare(i, 2, ": ") == 0 ? i + 2 : std::string::npos;
}

// `KEY: what` with a non-empty key and what.
bool key_and_what(const std::string& m, std::size_t from) {
  const std::size_t colon = m.find(": ", from);
  return colon != std::string::npos && colon > from && colon + 2 < m.size();
}

} // namespace

bool well_formed(const std::string& target, const std::string& m) {
  if (m.empty()) return true;
  if (m.find('\n') != std::string::npos) return false;
  if (target == "scene") {
    const std::size_t at = after_line(m, "fuzz/scene.yaml");
    return at != std::string::npos && key_and_what(m, at);
  }
  if (target == "override") {
    if (m.rfind("--set ", 0) == 0) return true;
    if (m.rfind(kBaseScene.string() + ": --set ", 0) == 0) return true;
    const std::size_t at = after_line(m, kBaseScene.string());
    return at != std::string::npos && key_and_what(m, at);
  }
  return after_line(m, "fuzz.msh") != std::string::npos ||
         (m.rfind("fuzz.msh: ", 0) == 0 && m.size() > 10);
}

} // namespace fsi::fuzz
