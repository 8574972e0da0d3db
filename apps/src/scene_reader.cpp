// Section: a block of the scene, its keys' paths and lines in messages, its sub-blocks, and the
// check that every key was read. The typed values: scene_values.cpp.
#include "fsi_app/scene_reader.hpp"

#include "fsi/core/error.hpp"
#include "scene_text.hpp"

#include <algorithm>

namespace fsi::app {

Section::Section(YAML::Node node, std::string path, ReadContext& ctx, int key_line)
    : node_(std::move(node)), path_(std::move(path)), ctx_(&ctx), key_line_(key_line) {
  if (ctx.documenting()) return;
  if (node_.IsDefined() && !node_.IsNull() && !node_.IsMap())
    fail("", "expected a block of keys, got " + scalar_text(node_));
  if (!node_.IsMap()) return;
  // yaml-cpp keeps every pair of a map but node[key] finds only the first: look for repeats.
  std::map<std::string, int> first_line;
  for (auto it = node_.begin(); it != node_.end(); ++it) {
    if (!it->first.IsScalar()) continue;
    const std::string key = it->first.Scalar();
    const int line = it->first.Mark().line + 1;
    const auto [seen, inserted] = first_line.emplace(key, line);
    if (!inserted) // an empty key is named as written, "" (key_path("") is the section's path)
      throw InputError(ctx.file + ":" + std::to_string(std::max(line, 1)) + ": " +
                       (key.empty() ? (path_.empty() ? "\"\"" : path_ + ".\"\"") : key_path(key)) +
                       ": duplicate key (first on line " +
                       std::to_string(std::max(seen->second, 1)) + "); give each key once");
  }
}

std::string Section::key_path(const std::string& key) const {
  if (key.empty()) return path_;
  const auto from = lifted_.find(key);
  const std::string name = from == lifted_.end() ? key : from->second + "." + key;
  return path_.empty() ? name : path_ + "." + name;
}

namespace {
/// A `--set` argument as messages show it: at most 120 characters.
std::string shown(const std::string& text) {
  return text.size() > 120 ? text.substr(0, 120) + "..." : text;
}
} // namespace

std::string Section::location(const std::string& key) const {
  const std::string full = key_path(key);
  for (const auto& [path, text] : ctx_->created)
    if (full == path || full.rfind(path + ".", 0) == 0 || full.rfind(path + "[", 0) == 0)
      return ctx_->file + ": --set " + shown(text);
  for (const auto& [path, text] : ctx_->overrides)
    if (full == path || full.rfind(path + ".", 0) == 0 || full.rfind(path + "[", 0) == 0 ||
        path.rfind(full + ".", 0) == 0 || path.rfind(full + "[", 0) == 0)
      return ctx_->file + ": --set " + shown(path + "=" + text);
  int line = key_line_ > 0 ? key_line_ : 1;
  if (!key.empty() && node_.IsMap())
    for (auto it = node_.begin(); it != node_.end(); ++it)
      if (it->first.Scalar() == key) line = std::max(1, it->first.Mark().line + 1);
  return ctx_->file + ":" + std::to_string(line);
}

void Section::fail(const std::string& key, const std::string& what) const {
  throw InputError(message(key, what));
}

std::string Section::message(const std::string& key, const std::string& what) const {
  const std::string name = key_path(key);
  return location(key) + ": " + (name.empty() ? "scene" : name) + ": " + what;
}

namespace {
int key_line_of(const YAML::Node& map, const std::string& key) {
  if (map.IsMap())
    for (auto it = map.begin(); it != map.end(); ++it)
      if (it->first.Scalar() == key) return it->first.Mark().line + 1;
  return 0;
}

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
      diagonal = up;
    }
  }
  return row[b.size()];
}
} // namespace

void Section::missing(const std::string& key) const {
  std::string hint;
  if (node_.IsMap())
    for (auto it = node_.begin(); it != node_.end(); ++it) {
      const std::string present = it->first.Scalar();
      if (present != key && edit_distance(present, key) <= 2)
        hint = " (is '" + present + "' on line " + std::to_string(it->first.Mark().line + 1) +
               " a misspelling?)";
    }
  const std::string full = key_path(key);
  for (const auto& [path, text] : ctx_->created)
    if (full.rfind(path + ".", 0) == 0 || full.rfind(path + "[", 0) == 0)
      hint += " (block '" + path + "' is not in the scene file: --set " + shown(text) +
              " created it, so give its required keys too)";
  fail(key, "required key missing" + hint);
}

void Section::lift(const std::string& key) {
  read_.push_back(key);
  if (ctx_->documenting() || !has(key)) return;
  const Section sub(node_[key], key_path(key), *ctx_, key_line_of(node_, key));
  if (!sub.node_.IsMap()) return;
  // A new map (node_ rebound, the scene's tree untouched) holding this block's pairs and the
  // sub-block's, each key node with its own line.
  YAML::Node merged(YAML::NodeType::Map);
  for (auto it = node_.begin(); it != node_.end(); ++it) merged.force_insert(it->first, it->second);
  for (auto it = sub.node_.begin(); it != sub.node_.end(); ++it) {
    const std::string name = it->first.Scalar();
    if (has(name))
      sub.fail(name, "also given as " + key_path(name) + " (" + location(name) + "); give it once");
    if (std::find(read_.begin(), read_.end(), name) != read_.end())
      sub.fail(name, "belongs in " + path_ + " itself (it is read before " + key_path(key) + ")");
    merged.force_insert(it->first, it->second);
    lifted_[name] = key;
  }
  node_.reset(merged);
}

void Section::set_aside(const std::string& key) {
  read_.push_back(key);
}

void Section::rebind(YAML::Node view) {
  node_.reset(view);
}

bool Section::has(const std::string& key) const {
  return node_.IsMap() && node_[key].IsDefined() && !node_[key].IsNull();
}

YAML::Node Section::get(const std::string& key, const std::string& type,
                        const std::string& fallback, const std::string& range,
                        const std::string& doc) {
  read_.push_back(key);
  if (ctx_->documenting()) {
    const std::string list_path = path_.empty() ? key : path_ + "." + key;
    ctx_->collector->push_back({list_path, type, fallback, range, doc});
    return YAML::Node(YAML::NodeType::Undefined);
  }
  if (!has(key)) return YAML::Node(YAML::NodeType::Undefined);
  return node_[key];
}

std::optional<Section> Section::block(const std::string& key, const std::string& doc) {
  const YAML::Node node = get(key, "block", "optional", "", doc);
  if (ctx_->documenting()) return Section(YAML::Node(), key_path(key), *ctx_);
  if (!node.IsDefined()) return std::nullopt;
  return Section(node, key_path(key), *ctx_, key_line_of(node_, key));
}

Section Section::required_block(const std::string& key, const std::string& doc) {
  const YAML::Node node = get(key, "block", "required", "", doc);
  if (!ctx_->documenting() && !node.IsDefined()) missing(key);
  return Section(node, key_path(key), *ctx_, key_line_of(node_, key));
}

std::vector<Section> Section::list(const std::string& key, const std::string& doc) {
  const YAML::Node node = get(key, "list of blocks", "[]", "", doc);
  if (ctx_->documenting()) return {Section(YAML::Node(), key_path(key) + "[]", *ctx_)};
  std::vector<Section> out;
  if (!node.IsDefined()) return out;
  if (!node.IsSequence()) fail(key, "expected a list of blocks (- key: value)");
  for (std::size_t i = 0; i < node.size(); ++i)
    out.emplace_back(node[i], key_path(key) + "[" + std::to_string(i) + "]", *ctx_,
                     node[i].Mark().line + 1);
  return out;
}

void Section::finish() const {
  if (ctx_->documenting() || !node_.IsMap()) return;
  for (auto it = node_.begin(); it != node_.end(); ++it) {
    const std::string key = it->first.Scalar();
    if (std::find(read_.begin(), read_.end(), key) == read_.end()) {
      std::vector<std::string> known = read_;
      std::sort(known.begin(), known.end());
      known.erase(std::unique(known.begin(), known.end()), known.end());
      fail(key, "unknown key (known here: " + join(known, ", ") + ")");
    }
  }
}

} // namespace fsi::app
