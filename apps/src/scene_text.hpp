#pragma once
// What the scene reader's files share: how a YAML value and a list of names show in messages.
#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

namespace fsi::app {

/// A scalar as written; otherwise what the node is ("a list", "a block", "nothing").
inline std::string scalar_text(const YAML::Node& node) {
  if (node.IsScalar()) return node.Scalar();
  if (node.IsSequence()) return "a list";
  if (node.IsMap()) return "a block";
  return "nothing";
}

inline std::string join(const std::vector<std::string>& items, const std::string& sep) {
  std::string out;
  for (std::size_t i = 0; i < items.size(); ++i) out += (i ? sep : "") + items[i];
  return out;
}

} // namespace fsi::app
