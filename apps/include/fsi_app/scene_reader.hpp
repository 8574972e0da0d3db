#pragma once
// Strict, typed access to one block of a scene file. Every key is declared exactly once, at the
// point where it is read: name, type, default, allowed range and a one-line doc. The same
// declarations produce the scene reference (docs/scenes.md) when read in documentation mode.
// Errors are one line, `FILE:LINE: KEY: what is wrong`, thrown as fsi::InputError.
#include "fsi/core/options.hpp"
#include "fsi/core/types.hpp"

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>
#include <yaml-cpp/yaml.h>

namespace fsi::app {

using fsi::Range; // fsi/core/options.hpp

/// One declared key, as the documentation generator sees it.
struct KeyDoc {
  std::string path;     ///< dotted path, lists shown as `structures[]`
  std::string type;     ///< "real", "integer", "bool", "string", "one of a|b", "[x, y]", ...
  std::string fallback; ///< default value as text, or "required"
  std::string range;
  std::string doc;
};

/// Shared state of one scene read: file name, overridden paths, documentation collector.
struct ReadContext {
  std::string file;                             ///< scene path as given, for messages
  std::filesystem::path dir;                    ///< relative file paths resolve here
  std::map<std::string, std::string> overrides; ///< dotted path -> `--set` text
  /// Blocks an override created because the file has none: dotted path -> the whole `--set`
  /// argument (a later "required key missing" inside says so).
  std::map<std::string, std::string> created;
  std::unique_ptr<std::vector<KeyDoc>> collector; ///< non-null in documentation mode
  int dimension = 2; ///< the scene's `dimension`: points are [x, y] or [x, y, z]

  bool documenting() const { return collector != nullptr; }
};

/// Largest scene file read (a FIFO, a device or a huge file is refused before reading).
constexpr std::uintmax_t kMaxSceneBytes = 16u << 20;

/// The text of a scene file: a regular file of at most kMaxSceneBytes. InputError `FILE: what`
/// for a missing file, a directory, a FIFO or device, an unreadable or oversized file.
std::string read_scene_file(const std::filesystem::path& file);

/// Parses a scene's text as exactly one YAML document. InputError `FILE:LINE: yaml: what` on a
/// syntax error and on a second document (naming the lines of both).
YAML::Node load_scene_yaml(const std::string& text, const std::string& file);

/// How many YAML documents `text` holds, counting at most `at_most` (parse errors propagate).
std::size_t yaml_documents(const std::string& text, std::size_t at_most);

class Section {
public:
  /// `key_line` is the 1-based line of the key that opened this block (0 for the top level).
  /// A key given twice in the block is an InputError naming both lines (yaml-cpp would keep
  /// the first silently).
  Section(YAML::Node node, std::string path, ReadContext& ctx, int key_line = 0);

  double real(const std::string& key, Range range, const std::string& doc);
  double real(const std::string& key, double fallback, Range range, const std::string& doc);
  std::optional<double> optional_real(const std::string& key, Range range, const std::string& doc);
  int integer(const std::string& key, Range range, const std::string& doc);
  std::optional<int> optional_integer(const std::string& key, Range range, const std::string& doc);
  int integer(const std::string& key, int fallback, Range range, const std::string& doc);
  bool boolean(const std::string& key, bool fallback, const std::string& doc);
  std::string text(const std::string& key, const std::string& fallback, const std::string& doc);
  std::string text(const std::string& key, const std::string& doc);
  std::string choice(const std::string& key, const std::vector<std::string>& choices,
                     const std::string& fallback, const std::string& doc);
  Vec2 vec2(const std::string& key, const std::string& doc);
  Vec2 vec2(const std::string& key, const Vec2& fallback, const std::string& doc);
  std::optional<Vec2> optional_vec2(const std::string& key, const std::string& doc);
  /// [x, y, z], in a scene of dimension 3 (documented with the 2-D key it stands for).
  Vec3 vec3(const std::string& key, const Vec3& fallback, const std::string& doc);
  std::optional<Vec3> optional_vec3(const std::string& key, const std::string& doc);
  std::vector<Vec2> points(const std::string& key, std::size_t min_count, const std::string& doc);
  std::vector<std::string> names(const std::string& key, const std::vector<std::string>& fallback,
                                 const std::string& doc);
  /// A file that must exist; relative paths resolve against the scene's directory.
  std::filesystem::path file(const std::string& key, const std::string& doc);

  std::optional<Section> block(const std::string& key, const std::string& doc);
  Section required_block(const std::string& key, const std::string& doc);
  /// A list of maps; each entry is a Section named `key[i]`.
  std::vector<Section> list(const std::string& key, const std::string& doc);

  bool has(const std::string& key) const;
  /// Reads sub-block `key` as part of this block: with `fluid.sph: {correction: none}`, lift("sph")
  /// makes `correction` a key of `fluid`, messages still naming fluid.sph.correction and its line.
  /// A key given both here and in the sub-block is an InputError naming both lines.
  void lift(const std::string& key);
  /// Marks `key` as read without reading it (a sub-block another reader has checked).
  void set_aside(const std::string& key);
  /// Reads `view` as this block from now on (a plug-in's translation of another type's keys,
  /// StructurePlugin::adopt): the keys read so far stay read; the scene's tree is untouched.
  void rebind(YAML::Node view);
  /// The block's keys and values, for a reader that checks a view of them.
  const YAML::Node& node() const { return node_; }
  /// Every key present must have been read: anything else is an unknown key.
  void finish() const;
  /// Throws the one-line error for `key` of this block (or the block itself if key is empty).
  [[noreturn]] void fail(const std::string& key, const std::string& what) const;
  /// That one-line error, `FILE:LINE: key: what`, for a refusal found later (e.g. under mpirun).
  std::string message(const std::string& key, const std::string& what) const;

  const std::string& path() const { return path_; }
  int line() const { return key_line_; }
  ReadContext& context() const { return *ctx_; }

private:
  YAML::Node get(const std::string& key, const std::string& type, const std::string& fallback,
                 const std::string& range, const std::string& doc);
  std::string key_path(const std::string& key) const;
  std::string location(const std::string& key) const;
  [[noreturn]] void missing(const std::string& key) const;

  YAML::Node node_;
  std::string path_;
  ReadContext* ctx_;
  int key_line_;
  mutable std::vector<std::string> read_;
  std::map<std::string, std::string> lifted_; ///< key -> the sub-block it was lifted from
};

/// Reads the options a component declares once (its visit_options, fsi/core/options.hpp) from
/// a block: each key with the component's default, range, names and doc.
class OptionReader final : public OptionVisitor {
public:
  explicit OptionReader(Section& s) : s_(s) {}
  void name(const std::string& key, std::string& value, const std::vector<std::string>& allowed,
            const std::string& doc) override {
    value = s_.choice(key, allowed, value, doc);
  }
  void real(const std::string& key, double& value, const Range& range,
            const std::string& doc) override {
    value = s_.real(key, value, range, doc);
  }
  void required(const std::string& key, double& value, const Range& range,
                const std::string& doc) override {
    value = s_.real(key, range, doc);
  }
  void integer(const std::string& key, int& value, const Range& range,
               const std::string& doc) override {
    value = s_.integer(key, value, range, doc);
  }
  void flag(const std::string& key, bool& value, const std::string& doc) override {
    value = s_.boolean(key, value, doc);
  }

private:
  Section& s_;
};

} // namespace fsi::app
