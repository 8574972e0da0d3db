#pragma once
// The two error channels for conditions a user can cause. Programmer invariants are asserts.
#include <stdexcept>
#include <string>

namespace fsi {

/// `text` with control characters escaped (`\n`, `\xNN`): user text quoted in a message (a key,
/// a value, a file name) cannot break it over several lines.
inline std::string one_line(const std::string& text) {
  std::string out;
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '\n') {
      out += "\\n";
    } else if (u < 0x20 || u == 0x7f) {
      const char* hex = "0123456789abcdef";
      out += {'\\', 'x', hex[u >> 4], hex[u & 15]};
    } else {
      out += c;
    }
  }
  return out;
}

/// Bad user input (scene, mesh, command line), detected before any computation.
/// The message is one line, `FILE:LINE: KEY: what is wrong` where a file is known. Exit status 2.
struct InputError : std::runtime_error {
  explicit InputError(const std::string& what) : std::runtime_error(one_line(what)) {}
};

/// A run that cannot go on (NaN, particle through a wall, Newton or coupling failure).
/// The message says what, where (particle, node, element) and when (step, time). Exit status 3.
struct RunError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

} // namespace fsi
