#include "fsi_app/scene_reader.hpp"

#include <yaml-cpp/eventhandler.h>

#include "fsi/core/error.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <yaml-cpp/depthguard.h>

namespace fsi::app {

namespace {

std::string format_number(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

std::string scalar_text(const YAML::Node& node) {
  if (node.IsScalar()) return node.Scalar();
  if (node.IsSequence()) return "a list";
  if (node.IsMap()) return "a block";
  return "nothing";
}

bool parse_real(const YAML::Node& node, double& out) {
  if (!node.IsScalar()) return false;
  const std::string& s = node.Scalar();
  char* end = nullptr;
  out = std::strtod(s.c_str(), &end);
  return !s.empty() && end == s.c_str() + s.size() && std::isfinite(out);
}

std::string join(const std::vector<std::string>& items, const std::string& sep) {
  std::string out;
  for (std::size_t i = 0; i < items.size(); ++i) out += (i ? sep : "") + items[i];
  return out;
}

} // namespace

std::string read_scene_file(const std::filesystem::path& file) {
  namespace fs = std::filesystem;
  const std::string name = file.string();
  std::error_code ec;
  const fs::file_status st = fs::status(file, ec);
  if (ec || !fs::exists(st)) throw InputError(name + ": cannot open scene file");
  if (fs::is_directory(st)) throw InputError(name + ": is a directory; give a scene file (.yaml)");
  if (!fs::is_regular_file(st))
    throw InputError(name + ": not a regular file (a FIFO, device or socket); give a scene file");
  const std::uintmax_t size = fs::file_size(file, ec);
  if (ec) throw InputError(name + ": cannot open scene file (" + ec.message() + ")");
  if (size > kMaxSceneBytes)
    throw InputError(name + ": " + std::to_string(size) + " bytes; a scene file is at most " +
                     std::to_string(kMaxSceneBytes >> 20) + " MiB");
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(name + ": cannot open scene file (" + std::strerror(errno) + ")");
  std::string text;
  text.reserve(static_cast<std::size_t>(size));
  text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  if (in.bad() || text.size() > kMaxSceneBytes) throw InputError(name + ": cannot read scene file");
  return text;
}

namespace {
/// Where each YAML document starts; the content of the documents is not kept.
struct DocumentStarts final : YAML::EventHandler {
  std::vector<YAML::Mark> marks;
  void OnDocumentStart(const YAML::Mark& mark) override { marks.push_back(mark); }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark&, YAML::anchor_t) override {}
  void OnAlias(const YAML::Mark&, YAML::anchor_t) override {}
  void OnScalar(const YAML::Mark&, const std::string&, YAML::anchor_t,
                const std::string&) override {}
  void OnSequenceStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                       YAML::EmitterStyle::value) override {}
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                  YAML::EmitterStyle::value) override {}
  void OnMapEnd() override {}
};
} // namespace

std::size_t yaml_documents(const std::string& text, std::size_t at_most) {
  DocumentStarts starts;
  std::istringstream in(text);
  YAML::Parser parser(in);
  while (starts.marks.size() < at_most && parser.HandleNextDocument(starts)) {
  }
  return starts.marks.size();
}

YAML::Node load_scene_yaml(const std::string& text, const std::string& file) {
  // The first document, then whether a second one starts: at most two documents are parsed
  // (YAML::LoadAll runs out of memory on some malformed inputs, making empty documents forever).
  YAML::Node first;
  DocumentStarts starts;
  try {
    first = YAML::Load(text);
    std::istringstream in(text);
    YAML::Parser parser(in);
    while (starts.marks.size() < 2 && parser.HandleNextDocument(starts)) {
    }
  } catch (const YAML::DeepRecursion& e) {
    throw InputError(file + ":" + std::to_string(e.mark.line + 1) + ": yaml: nested too deeply (" +
                     std::to_string(e.depth()) + " levels)");
  } catch (const YAML::ParserException& e) {
    throw InputError(file + ":" + std::to_string(e.mark.line + 1) + ": yaml: " + e.msg);
  }
  if (starts.marks.size() > 1) {
    // The line of the '---' that opens the second document: the last separator line at or
    // before its content (a document of nothing but '---' has no mark).
    const int content = starts.marks[1].line + 1;
    int second = content, line = 1;
    for (std::size_t i = 0; i <= text.size(); ++i) {
      const bool start = i == 0 || text[i - 1] == '\n';
      if (start && text.compare(i, 3, "---") == 0 &&
          (i + 3 >= text.size() || std::isspace(static_cast<unsigned char>(text[i + 3]))) &&
          (content <= 0 || line <= content))
        second = line;
      if (i < text.size() && text[i] == '\n') ++line;
    }
    throw InputError(file + ":" + std::to_string(std::max(second, 1)) +
                     ": yaml: a second YAML document (the scene is the document of line " +
                     std::to_string(std::max(starts.marks[0].line + 1, 1)) +
                     "); a scene file holds one document: remove the '---' and what follows");
  }
  return first;
}

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

double Section::real(const std::string& key, Range range, const std::string& doc) {
  const auto value = optional_real(key, range, doc);
  if (ctx_->documenting()) {
    ctx_->collector->back().fallback = "required";
    return std::isfinite(range.lo) ? range.lo : 0.0;
  }
  if (!value) missing(key);
  return *value;
}

double Section::real(const std::string& key, double fallback, Range range, const std::string& doc) {
  const auto value = optional_real(key, range, doc);
  if (ctx_->documenting()) ctx_->collector->back().fallback = format_number(fallback);
  return value.value_or(fallback);
}

std::optional<double> Section::optional_real(const std::string& key, Range range,
                                             const std::string& doc) {
  const YAML::Node node = get(key, "real", "optional", range.describe(), doc);
  if (!node.IsDefined()) return std::nullopt;
  double v = 0.0;
  if (!parse_real(node, v)) fail(key, "expected a real number, got '" + scalar_text(node) + "'");
  if (!range.contains(v)) fail(key, "must be " + range.describe() + ", got " + format_number(v));
  return v;
}

std::optional<int> Section::optional_integer(const std::string& key, Range range,
                                             const std::string& doc) {
  const YAML::Node node = get(key, "integer", "optional", range.describe(), doc);
  if (!node.IsDefined()) return std::nullopt;
  double v = 0.0;
  if (!parse_real(node, v) || v != std::floor(v) || std::abs(v) > 1e9)
    fail(key, "expected an integer, got '" + scalar_text(node) + "'");
  if (!range.contains(v)) fail(key, "must be " + range.describe() + ", got " + format_number(v));
  return static_cast<int>(v);
}

int Section::integer(const std::string& key, Range range, const std::string& doc) {
  const auto value = optional_integer(key, range, doc);
  if (ctx_->documenting()) {
    ctx_->collector->back().fallback = "required";
    return std::isfinite(range.lo) ? static_cast<int>(range.lo) : 0;
  }
  if (!value) missing(key);
  return *value;
}

int Section::integer(const std::string& key, int fallback, Range range, const std::string& doc) {
  const auto value = optional_integer(key, range, doc);
  if (ctx_->documenting()) ctx_->collector->back().fallback = std::to_string(fallback);
  return value.value_or(fallback);
}

bool Section::boolean(const std::string& key, bool fallback, const std::string& doc) {
  const YAML::Node node = get(key, "bool", fallback ? "true" : "false", "", doc);
  if (!node.IsDefined()) return fallback;
  const std::string s = node.IsScalar() ? node.Scalar() : "";
  if (s == "true") return true;
  if (s == "false") return false;
  fail(key, "expected true or false, got '" + scalar_text(node) + "'");
}

std::string Section::text(const std::string& key, const std::string& fallback,
                          const std::string& doc) {
  const YAML::Node node = get(key, "string", fallback.empty() ? "\"\"" : fallback, "", doc);
  if (!node.IsDefined()) return fallback;
  if (!node.IsScalar()) fail(key, "expected a string, got " + scalar_text(node));
  return node.Scalar();
}

std::string Section::text(const std::string& key, const std::string& doc) {
  const YAML::Node node = get(key, "string", "required", "", doc);
  if (ctx_->documenting()) return "";
  if (!node.IsDefined()) missing(key);
  if (!node.IsScalar() || node.Scalar().empty())
    fail(key, "expected a non-empty string, got " + scalar_text(node));
  return node.Scalar();
}

std::string Section::choice(const std::string& key, const std::vector<std::string>& choices,
                            const std::string& fallback, const std::string& doc) {
  const YAML::Node node = get(key, "one of " + join(choices, " \\| "),
                              fallback.empty() ? "required" : fallback, "", doc);
  if (ctx_->documenting()) return fallback.empty() ? choices.front() : fallback;
  if (!node.IsDefined()) {
    if (fallback.empty()) missing(key);
    return fallback;
  }
  const std::string s = node.IsScalar() ? node.Scalar() : "";
  if (std::find(choices.begin(), choices.end(), s) == choices.end())
    fail(key, "expected one of " + join(choices, ", ") + ", got '" + scalar_text(node) + "'");
  return s;
}

namespace {
template <int D> bool parse_vec(const YAML::Node& node, VecD<D>& out) {
  if (!node.IsSequence() || node.size() != D) return false;
  for (int i = 0; i < D; ++i)
    if (!parse_real(node[i], out[i])) return false;
  return true;
}

// A point of the other dimension says which dimension the scene is.
template <int D> std::string expected_point(const YAML::Node& node) {
  const bool other = node.IsSequence() && node.size() == 5 - D;
  if constexpr (D == 2)
    return other ? "expected [x, y]: the scene is 2-D (give dimension: 3 for [x, y, z])"
                 : "expected a pair of real numbers [x, y]";
  else
    return other ? "expected [x, y, z]: the scene is 3-D (dimension: 3)"
                 : "expected three real numbers [x, y, z]";
}
} // namespace

namespace {
/// The point `node` holds, or nothing when the key is absent; a bad one fails naming `key`.
template <int D>
std::optional<VecD<D>> point(const Section& s, const std::string& key, const YAML::Node& node) {
  if (!node.IsDefined()) return std::nullopt;
  VecD<D> v;
  if (!parse_vec<D>(node, v)) s.fail(key, expected_point<D>(node));
  return v;
}
} // namespace

Vec2 Section::vec2(const std::string& key, const std::string& doc) {
  const auto v = point<2>(*this, key, get(key, "[x, y]", "required", "", doc));
  if (ctx_->documenting()) return Vec2::Zero();
  if (!v) missing(key);
  return *v;
}

Vec2 Section::vec2(const std::string& key, const Vec2& fallback, const std::string& doc) {
  const std::string shown =
      "[" + format_number(fallback.x()) + ", " + format_number(fallback.y()) + "]";
  return point<2>(*this, key, get(key, "[x, y]", shown, "", doc)).value_or(fallback);
}

std::optional<Vec2> Section::optional_vec2(const std::string& key, const std::string& doc) {
  return point<2>(*this, key, get(key, "[x, y]", "optional", "", doc));
}

Vec3 Section::vec3(const std::string& key, const Vec3& fallback, const std::string& doc) {
  return optional_vec3(key, doc).value_or(fallback);
}

std::optional<Vec3> Section::optional_vec3(const std::string& key, const std::string& doc) {
  return point<3>(*this, key, get(key, "[x, y, z]", "optional", "", doc));
}

std::vector<Vec2> Section::points(const std::string& key, std::size_t min_count,
                                  const std::string& doc) {
  const YAML::Node node = get(key, "[[x, y], ...]", "required",
                              "at least " + std::to_string(min_count) + " points", doc);
  if (ctx_->documenting()) return {};
  if (!node.IsDefined()) missing(key);
  if (!node.IsSequence()) fail(key, "expected a list of points [[x, y], ...]");
  std::vector<Vec2> pts;
  for (const auto& item : node) {
    Vec2 v;
    if (!parse_vec<2>(item, v))
      fail(key, "point " + std::to_string(pts.size()) + " is not a pair of real numbers [x, y]");
    pts.push_back(v);
  }
  if (pts.size() < min_count)
    fail(key, "needs at least " + std::to_string(min_count) + " points, got " +
                  std::to_string(pts.size()));
  return pts;
}

std::vector<std::string> Section::names(const std::string& key,
                                        const std::vector<std::string>& fallback,
                                        const std::string& doc) {
  const YAML::Node node =
      get(key, "[name, ...]", fallback.empty() ? "[]" : "[" + join(fallback, ", ") + "]", "", doc);
  if (!node.IsDefined()) return fallback;
  std::vector<std::string> out;
  if (node.IsScalar()) return {node.Scalar()};
  if (!node.IsSequence()) fail(key, "expected a list of names");
  for (const auto& item : node) {
    if (!item.IsScalar()) fail(key, "expected a list of names");
    out.push_back(item.Scalar());
  }
  return out;
}

std::filesystem::path Section::file(const std::string& key, const std::string& doc) {
  const YAML::Node node = get(key, "file path", "required", "relative to the scene file", doc);
  if (ctx_->documenting()) return {};
  if (!node.IsDefined()) missing(key);
  if (!node.IsScalar()) fail(key, "expected a file path");
  std::filesystem::path p = node.Scalar();
  if (p.is_relative()) p = ctx_->dir / p;
  std::error_code ec;
  // Say what the path is when it is not a file (issue 41: a folder, FIFO or device).
  const std::filesystem::file_status st = std::filesystem::status(p, ec);
  if (ec || !std::filesystem::exists(st)) fail(key, "file not found: " + p.string());
  if (std::filesystem::is_directory(st)) fail(key, p.string() + " is a folder; give a file");
  if (!std::filesystem::is_regular_file(st))
    fail(key, p.string() + " is not a regular file (a FIFO, device or socket); give a file");
  return p;
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
