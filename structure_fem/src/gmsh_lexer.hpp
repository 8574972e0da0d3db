#pragma once
// The Gmsh reader's tokeniser (private to structure_fem): a .msh file held whole, read as ASCII
// tokens or binary values, and the messages that name where in the file a problem is.
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <utility>

#include "fsi/core/error.hpp"

namespace fsi::fem::gmsh {

/// Largest integer accepted anywhere (tags, counts): far beyond any real mesh, small enough that
/// no count or sign flip overflows.
inline constexpr long kLargest = 1L << 40;

/// A token or a stretch of a file as a message may show it: at most 40 characters, control and
/// non-ASCII bytes escaped as \xNN (a binary file never floods the terminal).
inline std::string shown(const std::string& t) {
  std::string out;
  for (std::size_t i = 0; i < t.size() && i < 40; ++i) {
    const auto c = static_cast<unsigned char>(t[i]);
    if (c >= 0x20 && c < 0x7f && c != '\\') {
      out += static_cast<char>(c);
    } else {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", c);
      out += buf;
    }
  }
  if (t.size() > 40) out += "...";
  return out;
}

/// A .msh file held whole: whitespace-separated tokens with the line each came from (ASCII), and
/// little-endian values at a byte offset (binary sections of `-bin` files). Messages name the
/// line (`FILE:LINE: what`) in ASCII files and the byte offset in binary ones (`FILE: byte N:`).
class Lexer {
public:
  Lexer(std::string data, std::string path) : path_(std::move(path)), data_(std::move(data)) {
    for (char c : data_) lines_ += c == '\n';
    if (!data_.empty() && data_.back() != '\n') ++lines_;
  }
  bool blank() const {
    return std::all_of(data_.begin(), data_.end(),
                       [](char c) { return std::isspace(static_cast<unsigned char>(c)); });
  }
  int line() const { return static_cast<int>(std::min(line_, std::max<long>(lines_, 1))); }
  const std::string& path() const { return path_; }
  void set_binary() { binary_ = true; }
  bool binary() const { return binary_; }
  /// "FILE:LINE: " (ASCII) or "FILE: byte N: " (binary).
  std::string where() const {
    return binary_ ? path_ + ": byte " + std::to_string(pos_) + ": "
                   : path_ + ":" + std::to_string(line()) + ": ";
  }
  [[noreturn]] void fail(const std::string& what) const { throw InputError(where() + what); }
  [[noreturn]] void end_of_file(const std::string& what) const {
    throw InputError((binary_ ? path_ + ": " : path_ + ":" + std::to_string(line()) + ": ") +
                     "unexpected end of file while reading " + what + " (truncated file?)");
  }
  std::string token(const std::string& what) {
    while (pos_ < data_.size() && std::isspace(static_cast<unsigned char>(data_[pos_])))
      line_ += data_[pos_++] == '\n';
    if (pos_ >= data_.size()) end_of_file(what);
    const std::size_t start = pos_;
    while (pos_ < data_.size() && !std::isspace(static_cast<unsigned char>(data_[pos_]))) ++pos_;
    return data_.substr(start, pos_ - start);
  }
  bool at_end() {
    while (pos_ < data_.size() && std::isspace(static_cast<unsigned char>(data_[pos_])))
      line_ += data_[pos_++] == '\n';
    return pos_ >= data_.size();
  }
  long integer(const std::string& what) {
    const std::string t = token(what);
    long v = 0;
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (ec != std::errc() || end != t.data() + t.size())
      fail("expected an integer for " + what + ", found \"" + shown(t) + "\"");
    return in_range(v, what);
  }
  double real(const std::string& what) {
    const std::string t = token(what);
    try {
      std::size_t used = 0;
      const double v = std::stod(t, &used);
      if (used == t.size() && std::isfinite(v)) return v;
    } catch (const std::exception&) {
    }
    fail("expected a finite number for " + what + ", found \"" + shown(t) + "\"");
  }
  /// The unread rest of the current line (used for quoted names).
  std::string rest_of_line() {
    const std::size_t end = std::min(data_.find('\n', pos_), data_.size());
    std::string r = data_.substr(pos_, end - pos_);
    pos_ = end;
    return r;
  }
  void expect(const std::string& keyword) {
    const std::string t = token(keyword);
    if (t != keyword) fail("expected " + keyword + ", found \"" + shown(t) + "\"");
  }
  /// The newline that ends an ASCII header line before binary data.
  void skip_newline() {
    if (pos_ < data_.size() && data_[pos_] == '\r') ++pos_;
    if (pos_ < data_.size() && data_[pos_] == '\n') ++pos_, ++line_;
  }
  /// The start of a msh 4.1 section's data: in a binary file, after the section's line.
  void begin_section() {
    if (binary_) skip_newline();
  }
  /// The `keyword` line that ends a msh 4.1 section (in a binary file, after the data's newline).
  void end_section(const std::string& keyword) {
    if (binary_) skip_newline();
    expect(keyword);
  }

  // Binary values (the file's data size is 8: size_t is 8 bytes, int 4, double 8).
  template <class T> T raw(const std::string& what) {
    if (data_.size() - pos_ < sizeof(T)) end_of_file(what);
    T v;
    std::memcpy(&v, data_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    return v;
  }
  long bin_int(const std::string& what) { return in_range(raw<std::int32_t>(what), what); }
  long bin_size(const std::string& what) {
    const std::size_t at = pos_;
    const auto v = raw<std::uint64_t>(what);
    if (v > static_cast<std::uint64_t>(kLargest)) {
      pos_ = at;
      fail(what + " " + std::to_string(v) + " is out of range");
    }
    return static_cast<long>(v);
  }
  double bin_real(const std::string& what) {
    const std::size_t at = pos_;
    const double v = raw<double>(what);
    if (!std::isfinite(v)) {
      pos_ = at;
      fail("expected a finite number for " + what + ", found " + std::to_string(v));
    }
    return v;
  }

  // The same read in the file's encoding: a count or tag stored as size_t in binary files, an
  // int tag, a double; text in ASCII files.
  long size(const std::string& what) { return binary_ ? bin_size(what) : integer(what); }
  long tag(const std::string& what) { return binary_ ? bin_int(what) : integer(what); }
  double number(const std::string& what) { return binary_ ? bin_real(what) : real(what); }

private:
  long in_range(long v, const std::string& what) const {
    if (v < -kLargest || v > kLargest) fail(what + " " + std::to_string(v) + " is out of range");
    return v;
  }

  std::string path_;
  std::string data_;
  std::size_t pos_ = 0;
  long line_ = 1, lines_ = 0;
  bool binary_ = false;
};

} // namespace fsi::fem::gmsh
