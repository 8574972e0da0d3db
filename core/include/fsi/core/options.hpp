#pragma once
// Options declared once. A component lists its options in one visit function (key, its member,
// allowed range or names, one-line doc; the member's initial value is the default). Readers,
// validators and documentation generators are OptionVisitors over that same list, so a key's
// default, range and doc cannot disagree between the component and the scene reader.
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace fsi {

/// Allowed interval of a number; open or closed at each end.
struct Range {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = false;
  bool hi_open = false;

  static Range any() { return {}; }
  static Range positive() { return {0.0, Range{}.hi, true, false}; }
  static Range non_negative() { return {0.0, Range{}.hi, false, false}; }
  static Range closed(double a, double b) { return {a, b, false, false}; }
  static Range open(double a, double b) { return {a, b, true, true}; }
  static Range left_open(double a, double b) { return {a, b, true, false}; }
  static Range right_open(double a, double b) { return {a, b, false, true}; }

  /// False for NaN.
  bool contains(double v) const {
    const bool above = lo_open ? v > lo : v >= lo;
    const bool below = hi_open ? v < hi : v <= hi;
    return above && below;
  }
  /// e.g. "in (0, 0.5)", "> 0", "any".
  std::string describe() const {
    const auto number = [](double v) {
      std::ostringstream out;
      out << v;
      return out.str();
    };
    const bool has_lo = std::isfinite(lo), has_hi = std::isfinite(hi);
    if (!has_lo && !has_hi) return "any";
    if (has_lo && !has_hi) return (lo_open ? "> " : ">= ") + number(lo);
    if (!has_lo) return (hi_open ? "< " : "<= ") + number(hi);
    return (lo_open ? "in (" : "in [") + number(lo) + ", " + number(hi) + (hi_open ? ")" : "]");
  }
};

/// What a component's visit function calls once per option, in declaration order.
class OptionVisitor {
public:
  virtual ~OptionVisitor() = default;
  /// A name from `allowed` (e.g. the registry's schemes).
  virtual void name(const std::string& key, std::string& value,
                    const std::vector<std::string>& allowed, const std::string& doc) = 0;
  virtual void real(const std::string& key, double& value, const Range& range,
                    const std::string& doc) = 0;
  virtual void integer(const std::string& key, int& value, const Range& range,
                       const std::string& doc) = 0;
  virtual void flag(const std::string& key, bool& value, const std::string& doc) = 0;
  /// A number the user must give (no default); a visitor without that notion reads it as real.
  virtual void required(const std::string& key, double& value, const Range& range,
                        const std::string& doc) {
    real(key, value, range, doc);
  }

  /// An enumeration, visited as one of its names (`names`: each value's name, in order).
  template <class E>
  void choice(const std::string& key, E& value, const std::vector<std::pair<std::string, E>>& names,
              const std::string& doc) {
    std::string text;
    std::vector<std::string> allowed;
    for (const auto& [n, e] : names) {
      allowed.push_back(n);
      if (e == value) text = n;
    }
    name(key, text, allowed, doc);
    for (const auto& [n, e] : names)
      if (n == text) value = e;
  }
};

} // namespace fsi
