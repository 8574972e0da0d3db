#pragma once
// The library side of the declared options: a visitor that checks every value against the range
// or the names its component declared, so a component never re-states a range by hand.
#include "fsi/core/error.hpp"
#include "fsi/core/options.hpp"

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

namespace fsi {

/// Throws InputError "PREFIX.KEY: value V is out of range: must be RANGE" (or "unknown name")
/// for the first declared option whose value its declaration does not allow.
class RangeChecker final : public OptionVisitor {
public:
  explicit RangeChecker(std::string prefix) : prefix_(std::move(prefix)) {}
  void name(const std::string& key, std::string& value, const std::vector<std::string>& allowed,
            const std::string&) override {
    if (std::find(allowed.begin(), allowed.end(), value) != allowed.end()) return;
    std::string names;
    for (const auto& n : allowed) names += (names.empty() ? "" : " ") + n;
    throw InputError(prefix_ + key + ": unknown name '" + value + "' (allowed: " + names + ")");
  }
  void real(const std::string& key, double& value, const Range& range,
            const std::string&) override {
    check(key, value, range);
  }
  void integer(const std::string& key, int& value, const Range& range,
               const std::string&) override {
    check(key, value, range);
  }
  void flag(const std::string&, bool&, const std::string&) override {}

private:
  void check(const std::string& key, double value, const Range& range) const {
    if (range.contains(value)) return;
    std::ostringstream text;
    text << value;
    throw InputError(prefix_ + key + ": value " + text.str() + " is out of range: must be " +
                     range.describe());
  }
  std::string prefix_;
};

} // namespace fsi
