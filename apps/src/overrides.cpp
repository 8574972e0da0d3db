#include "fsi_app/overrides.hpp"

#include "fsi/core/error.hpp"

#include <algorithm>
#include <cctype>
#include <optional>
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

/// Puts `entry` in `container`'s existing slot `step` (a map key or a list index) without
/// assigning through the slot's old node, which a YAML alias may share with other slots. The
/// slots after it are taken out and put back: the order and the other slots' nodes stay.
void replace_slot(YAML::Node& container, const Step& step, const YAML::Node& entry) {
  if (step.index >= 0) {
    std::vector<YAML::Node> tail;
    for (auto i = static_cast<std::size_t>(step.index); i < container.size(); ++i)
      tail.push_back(container[i]);
    for (std::size_t i = container.size(); i-- > static_cast<std::size_t>(step.index);)
      container.remove(i);
    container.push_back(entry);
    for (std::size_t i = 1; i < tail.size(); ++i) container.push_back(tail[i]);
    return;
  }
  std::vector<std::pair<YAML::Node, YAML::Node>> tail;
  for (const auto& kv : container)
    if (!tail.empty() || (kv.first.IsScalar() && kv.first.Scalar() == step.key))
      tail.emplace_back(kv.first, kv.second);
  for (const auto& kv : tail) container.remove(kv.first.Scalar());
  for (const auto& [key, value] : tail)
    container.force_insert(key, key.Scalar() == step.key ? entry : value);
}

/// The child at `step` if `node` has it.
std::optional<YAML::Node> child(const YAML::Node& node, const Step& step) {
  if (step.index >= 0) {
    if (!node.IsSequence() || step.index >= static_cast<long>(node.size())) return std::nullopt;
    return node[static_cast<std::size_t>(step.index)];
  }
  if (!node.IsMap() || !node[step.key]) return std::nullopt;
  return node[step.key];
}

} // namespace

void unshare_override_paths(YAML::Node& root, const std::vector<std::string>& overrides,
                            const std::function<YAML::Node()>& reparse) {
  for (const auto& text : overrides) {
    const std::size_t eq = text.find('=');
    if (eq == std::string::npos || eq == 0) continue;
    std::vector<Step> steps;
    try {
      steps = parse_path(text.substr(0, eq), text, "");
    } catch (const InputError&) {
      continue;
    }
    YAML::Node node = root;
    for (std::size_t k = 0; k < steps.size() && child(node, steps[k]); ++k) {
      std::optional<YAML::Node> copy = reparse(); // pristine: no override has applied yet
      for (std::size_t j = 0; j <= k && copy; ++j) copy = child(*copy, steps[j]);
      if (!copy) break;
      replace_slot(node, steps[k], *copy);
      node.reset(*copy);
    }
  }
}

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
    // One value: a second document (`1\n---\n7`) would be dropped silently (issue 41).
    if (yaml_documents(value_text, 2) > 1)
      throw InputError(where + path +
                       ": the value holds a second YAML document (a '---' line); give one value");
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
