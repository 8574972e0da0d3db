#include "fsi_app/overrides.hpp"

#include "fsi/core/error.hpp"

#include <algorithm>
#include <cctype>
#include <yaml-cpp/depthguard.h>

namespace fsi::app {

namespace {

struct Step {
  std::string key; ///< map key, or empty for a list index
  long index = -1;
};

std::vector<Step> parse_path(const std::string& path, const std::string& text,
                             const std::string& file) {
  auto bad = [&](const std::string& what) {
    const std::string shown = text.size() > 120 ? text.substr(0, 120) + "..." : text;
    return InputError(file + ": --set " + shown + ": " + path + ": " + what);
  };
  std::vector<Step> steps;
  std::size_t i = 0;
  while (i < path.size()) {
    std::size_t j = i;
    while (j < path.size() && path[j] != '.' && path[j] != '[') ++j;
    if (j == i) throw bad("empty key in path");
    const std::string key = path.substr(i, j - i);
    if (!std::all_of(key.begin(), key.end(), [](char c) {
          return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
        }))
      throw bad("'" + key + "' is not a scene key (letters, digits and _)");
    steps.push_back({key});
    while (j < path.size() && path[j] == '[') {
      const std::size_t close = path.find(']', j);
      const std::string digits =
          close == std::string::npos ? "" : path.substr(j + 1, close - j - 1);
      if (digits.empty() || digits.size() > 6 ||
          !std::all_of(digits.begin(), digits.end(), [](char c) { return std::isdigit(c); }))
        throw bad("malformed list index");
      steps.push_back({"", std::stol(digits)});
      j = close + 1;
    }
    if (j < path.size() && path[j] != '.') throw bad("malformed path");
    i = j + 1;
    if (j + 1 == path.size()) throw bad("path ends with '.'");
  }
  return steps;
}

} // namespace

void apply_override(YAML::Node& root, const std::string& text, ReadContext& ctx) {
  // Every message names the scene file the override applies to, then the argument (at most
  // 120 characters of it).
  const std::string shown = text.size() > 120 ? text.substr(0, 120) + "..." : text;
  const std::string where = ctx.file + ": --set " + shown + ": ";
  const std::size_t eq = text.find('=');
  if (eq == std::string::npos || eq == 0) throw InputError(where + "expected key.path=value");
  const std::string path = text.substr(0, eq);
  const std::string value_text = text.substr(eq + 1);
  const std::vector<Step> steps = parse_path(path, text, ctx.file);
  YAML::Node value;
  try {
    value = YAML::Load(value_text);
  } catch (const YAML::DeepRecursion& e) {
    throw InputError(where + path + ": value nested too deeply (" + std::to_string(e.depth()) +
                     " levels)");
  } catch (const YAML::Exception& e) {
    throw InputError(where + path + ": value is not valid YAML: " + e.msg);
  }
  YAML::Node node = root;
  std::string reached; // dotted path of `node`
  bool creating = false;
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const Step& s = steps[k];
    if (s.index >= 0) {
      reached.append("[").append(std::to_string(s.index)).append("]");
    } else {
      if (!reached.empty()) reached.push_back('.');
      reached.append(s.key);
    }
    const bool last = k + 1 == steps.size();
    if (s.index >= 0) {
      if (!node.IsSequence() || s.index >= static_cast<long>(node.size()))
        throw InputError(where + path + ": list index " + std::to_string(s.index) +
                         " does not exist");
      if (last) {
        node[static_cast<std::size_t>(s.index)] = value;
        break;
      }
      node.reset(node[static_cast<std::size_t>(s.index)]);
    } else {
      if (node.IsDefined() && !node.IsNull() && !node.IsMap())
        throw InputError(where + path + ": '" + s.key + "' is inside a value");
      if (last) {
        node[s.key] = value;
        break;
      }
      if (!node[s.key].IsDefined() || node[s.key].IsNull()) {
        node[s.key] = YAML::Node(YAML::NodeType::Map);
        if (!creating && !ctx.created.count(reached)) ctx.created[reached] = text;
        creating = true;
      }
      YAML::Node child = node[s.key];
      node.reset(child);
    }
  }
  ctx.overrides[path] = value_text;
}

} // namespace fsi::app
