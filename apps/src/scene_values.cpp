// Section's typed values (real, integer, bool, text, choice, points, names, file), each checked
// against its range and named in the message when it does not fit.
#include "fsi_app/scene_reader.hpp"

#include "scene_text.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace fsi::app {

namespace {

std::string format_number(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

bool parse_real(const YAML::Node& node, double& out) {
  if (!node.IsScalar()) return false;
  const std::string& s = node.Scalar();
  char* end = nullptr;
  out = std::strtod(s.c_str(), &end);
  return !s.empty() && end == s.c_str() + s.size() && std::isfinite(out);
}

} // namespace

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

} // namespace fsi::app
